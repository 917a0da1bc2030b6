#pragma once
// A photo file's pixels, scaled down on the way in: JPEG through libjpeg-turbo's scaled decoding
// (a 12 MP photo read at 1/8 costs a few milliseconds), HEIC/HEIF through libheif (its stored
// thumbnail when that is big enough, else the image decoded and shrunk). The result is upright:
// a JPEG's EXIF orientation is applied here, a HEIF's rotation and mirroring by libheif itself.
// Not in the browser's build (libheif): the page asks `trailray serve` for thumbnails.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/pins/photo_image.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "track/photos/photo.hpp"

namespace trailray::scene {

// A photo that cannot be read or decoded; the message names the file and what is wrong.
class PhotoDecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PhotoDecodeLimits {
  // Files larger than this are refused unread (no camera writes a JPEG or HEIC this big; a
  // panorama stitched to 200 MB is not worth seconds of decoding for a thumbnail).
  std::uintmax_t max_file_bytes = 64ull << 20;
  // Images with more pixels than this are refused before decoding (a hostile header).
  std::uint64_t max_pixels = 400'000'000ull;
};

// The photo at `path` scaled so that its long side is at most `long_side_px` (never enlarged),
// averaged over each output pixel's footprint; `exif_orientation` (1..8, EXIF's Orientation:
// other values are taken as 1) turns a JPEG upright. Throws PhotoDecodeError.
RgbaImage decode_photo(const std::string& path, int long_side_px, int exif_orientation,
                       const PhotoDecodeLimits& limits = {});

// The photos' thumbnails for their pins (long side `long_side_px`), in order; a photo that cannot
// be decoded gets nullptr and a warning naming it ("...: drawn as a plain pin"), the others go on.
std::vector<std::shared_ptr<const PhotoImage>> decode_thumbnails(const std::vector<track::PlacedPhoto>& photos,
                                                                 int long_side_px, Diagnostics& diagnostics,
                                                                 const PhotoDecodeLimits& limits = {});

// The pixels of `image` turned upright from EXIF orientation 1..8 (exposed for tests).
RgbaImage apply_exif_orientation(const RgbaImage& image, int exif_orientation);

// `image` shrunk so that its long side is at most `long_side_px`, by area averaging (exposed for tests).
RgbaImage shrink_to_long_side(const RgbaImage& image, int long_side_px);

}  // namespace trailray::scene
