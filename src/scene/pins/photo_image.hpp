#pragma once
// A photo's pixels, small (the thumbnail on its pin) or larger (the film's pause, the viewer's
// window), decoded from the photo's file (scene/pins/photo_decode.hpp, not in the browser's build:
// the page gets its thumbnails from `trailray serve`). Plain data the labels pass draws from.

#include <atomic>
#include <cstdint>
#include <memory>

#include "scene/pictures/rgba_image.hpp"

namespace trailray::scene {

// Pixels upright (the EXIF orientation applied), sRGB, opaque. `id` is unique in the process, so
// the labels pass's atlas can keep a thumbnail by it however many scenes come and go.
struct PhotoImage {
  std::uint64_t id = 0;
  RgbaImage pixels;
};

inline std::uint64_t next_photo_image_id() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

inline std::shared_ptr<const PhotoImage> make_photo_image(RgbaImage pixels) {
  return std::make_shared<const PhotoImage>(PhotoImage{next_photo_image_id(), std::move(pixels)});
}

}  // namespace trailray::scene
