#pragma once
// Reading a photo's EXIF block (JPEG, and HEIC/HEIF through exiv2's BMFF support) into a
// PhotoMetadata. Every problem is a Diagnostic naming the file: a photo that cannot be read at all
// (not an image, not JPEG or HEIC, enormous, an EXIF block exiv2 refuses) is an error and the caller
// goes on with the other photos; a field that is there but unusable (a GPS latitude with a zero
// denominator, an empty DateTimeOriginal, exiv2's own complaints about the block) is a warning
// and the rest is read.
//
// This header does not include exiv2, but exif_reader.cpp links it: the browser build leaves it out.
// Calls from several threads are safe: exiv2 0.27's set-up (XMP toolkit, log handler, BMFF switch)
// runs once, and the parsing itself is serialized (exiv2's globals are not thread-safe).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/photos/photo.hpp"

namespace trailray::track {

struct PhotoReadOptions {
  // A photo file bigger than this is refused unread (a phone's HEIC is a few MB, a camera's
  // JPEG 10-30 MB; a panorama 100 MB).
  std::int64_t max_bytes = std::int64_t{256} << 20;
};

struct PhotoReadResult {
  PhotoMetadata photo;                // path set; the rest NaN/empty where the file says nothing
  std::vector<Diagnostic> warnings;
  std::optional<Diagnostic> error;    // set: nothing was read (photo holds only the path)
  bool ok() const { return !error.has_value(); }
};

// The file at `path` (read whole into memory, then parsed).
PhotoReadResult read_photo_file(const std::string& path, const PhotoReadOptions& options = {});

// Bytes in memory as the photo `display_name` (the fuzzer's way in).
PhotoReadResult read_photo_bytes(const std::uint8_t* data, std::size_t size, const std::string& display_name,
                                 const PhotoReadOptions& options = {});

}  // namespace trailray::track
