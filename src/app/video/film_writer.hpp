#pragma once
// Where a film's frames go (`trailray video`): a video file encoded by libavcodec (MP4 with
// H.264, or WebM with VP9, chosen by the file's extension), or a folder of numbered PNGs. A video
// file is written into a temporary file next to it and renamed over it only by finish(), so an
// error or Ctrl-C (the writer destroyed before finish) leaves no broken file and any earlier one
// as it was.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "scene/pictures/rgba_image.hpp"

namespace trailray::app {

class FilmWriter {
 public:
  virtual ~FilmWriter() = default;
  // The next frame (the size given when opening). Throws std::runtime_error naming the output.
  virtual void add(const scene::RgbaImage& frame) = 0;
  // Flushes and puts the film in place. Throws std::runtime_error naming the output.
  virtual void finish() = 0;
};

enum class VideoCodec { h264, vp9 };

struct VideoSettings {
  std::uint32_t width = 0, height = 0;  // even numbers (4:2:0 chroma)
  double fps = 30.0;
  int crf = 20;  // quality: lower is better and larger (H.264 0..51, VP9 0..63)
};

// The codec a file name asks for: .mp4, .m4v, .mov -> H.264; .webm -> VP9; nullopt otherwise.
std::optional<VideoCodec> codec_for_path(const std::string& path);

// Opens `path` (its codec from codec_for_path) for writing. Throws std::runtime_error naming it:
// an unknown extension, an odd size, an encoder missing from the system's libavcodec.
std::unique_ptr<FilmWriter> open_video_file(const std::string& path, const VideoSettings& settings);

// Frames as frame_000001.png, ... in `folder` (created when missing), each written atomically.
std::unique_ptr<FilmWriter> open_frames_folder(const std::string& folder);

}  // namespace trailray::app
