// A film as a video file through libavformat/libavcodec/libswscale (Debian's FFmpeg): frames
// converted from 8-bit sRGB RGBA to BT.709 limited-range YUV 4:2:0, encoded at a constant frame
// rate and muxed into a temporary file that finish() renames over the target.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "app/common/output_file.hpp"
#include "app/video/film_writer.hpp"

namespace trailray::app {
namespace {

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

class VideoFile final : public FilmWriter {
 public:
  VideoFile(const std::string& path, VideoCodec codec, const VideoSettings& s)
      : path_(path), temporary_(temporary_path_next_to(path)), settings_(s) {
    try {
      open(codec);
    } catch (...) {
      close();
      throw;
    }
  }
  ~VideoFile() override { close(); }

  void add(const scene::RgbaImage& image) override {
    if (image.width != settings_.width || image.height != settings_.height)
      throw fail(fmt::format("a frame of {}x{} in a film of {}x{}", image.width, image.height, settings_.width,
                             settings_.height));
    check(av_frame_make_writable(frame_), "cannot reuse the frame");
    const std::uint8_t* src[1] = {image.rgba.data()};
    const int stride[1] = {static_cast<int>(image.width * 4)};
    sws_scale(sws_, src, stride, 0, static_cast<int>(image.height), frame_->data, frame_->linesize);
    frame_->pts = next_pts_++;
    send(frame_);
  }

  void finish() override {
    send(nullptr);
    check(av_write_trailer(format_), "cannot finish the file");
    check(avio_closep(&format_->pb), "cannot close the file");
    replace_with_temporary(temporary_, path_);
    finished_ = true;
  }

 private:
  std::runtime_error fail(const std::string& why) const { return std::runtime_error(path_ + ": " + why); }
  void check(int code, const char* what) const {
    if (code < 0) throw fail(fmt::format("{}: {}", what, av_message(code)));
  }

  void open(VideoCodec codec) {
    if (settings_.width % 2 != 0 || settings_.height % 2 != 0)
      throw fail(fmt::format("a video needs an even width and height (4:2:0 chroma), not {}x{}", settings_.width,
                             settings_.height));
    const bool h264 = codec == VideoCodec::h264;
    av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are noise on a terminal
    check(avformat_alloc_output_context2(&format_, nullptr, h264 ? "mp4" : "webm", temporary_.c_str()),
          "cannot set up the container");
    // No library versions or dates in the file: the same frames give the same bytes.
    format_->flags |= AVFMT_FLAG_BITEXACT;
    const char* encoder_name = h264 ? "libx264" : "libvpx-vp9";
    const AVCodec* encoder = avcodec_find_encoder_by_name(encoder_name);
    if (encoder == nullptr) throw fail(fmt::format("this libavcodec has no {} encoder", encoder_name));
    stream_ = avformat_new_stream(format_, nullptr);
    codec_ = avcodec_alloc_context3(encoder);
    if (stream_ == nullptr || codec_ == nullptr) throw fail("out of memory");
    codec_->width = static_cast<int>(settings_.width);
    codec_->height = static_cast<int>(settings_.height);
    const AVRational rate = av_d2q(settings_.fps, 100000);
    codec_->time_base = av_inv_q(rate);
    codec_->framerate = rate;
    codec_->pix_fmt = AV_PIX_FMT_YUV420P;
    codec_->gop_size = std::max(1, static_cast<int>(std::lround(settings_.fps * 2.0)));  // seekable every 2 s
    codec_->color_range = AVCOL_RANGE_MPEG;
    codec_->colorspace = AVCOL_SPC_BT709;
    codec_->color_primaries = AVCOL_PRI_BT709;
    codec_->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB encoded
    codec_->flags |= AV_CODEC_FLAG_BITEXACT;
    // The encoders' output depends on their thread count, which by default follows the machine's
    // cores: a fixed count gives the same file on every machine.
    codec_->thread_count = 4;
    if ((format_->oformat->flags & AVFMT_GLOBALHEADER) != 0) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    av_dict_set(&options, "crf", std::to_string(settings_.crf).c_str(), 0);
    if (h264) {
      av_dict_set(&options, "preset", "medium", 0);
      av_dict_set(&options, "profile", "high", 0);
      // No macroblock-tree rate control: with it, x264's assembly gives a different stream from
      // run to run in this process at some frame sizes (320x180, 320x192; the same frames
      // through the ffmpeg program do not), a read of memory whose content depends on what the
      // renderer left in the heap; with mbtree=0 (or asm=0) the file is the same every time.
      // The cost: about 1.5x the bytes at the same --crf (SSIM 0.9980 against 0.9967 of the
      // frames); --crf 24 gives about the size and quality that 20 gave with it.
      av_dict_set(&options, "x264-params", "mbtree=0", 0);
    } else {
      codec_->bit_rate = 0;  // constant quality
      av_dict_set(&options, "deadline", "good", 0);
      av_dict_set(&options, "cpu-used", "4", 0);
      av_dict_set(&options, "row-mt", "1", 0);
    }
    const int opened = avcodec_open2(codec_, encoder, &options);
    av_dict_free(&options);
    check(opened, "cannot open the encoder");
    check(avcodec_parameters_from_context(stream_->codecpar, codec_), "cannot describe the stream");
    stream_->time_base = codec_->time_base;
    stream_->avg_frame_rate = rate;
    check(avio_open(&format_->pb, temporary_.c_str(), AVIO_FLAG_WRITE), "cannot create a temporary file in its folder");
    AVDictionary* muxing = nullptr;
    if (h264) av_dict_set(&muxing, "movflags", "+faststart", 0);  // the index first: plays while it loads
    const int header = avformat_write_header(format_, &muxing);
    av_dict_free(&muxing);
    check(header, "cannot write the header");

    frame_ = av_frame_alloc();
    packet_ = av_packet_alloc();
    if (frame_ == nullptr || packet_ == nullptr) throw fail("out of memory");
    frame_->format = AV_PIX_FMT_YUV420P;
    frame_->width = codec_->width;
    frame_->height = codec_->height;
    check(av_frame_get_buffer(frame_, 0), "cannot allocate a frame");
    sws_ = sws_getContext(codec_->width, codec_->height, AV_PIX_FMT_RGBA, codec_->width, codec_->height,
                          AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr,
                          nullptr);
    if (sws_ == nullptr) throw fail("cannot set up the colour conversion");
    // BT.709 coefficients, full-range RGB in, limited-range YUV out (what players expect of HD video).
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(sws_, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  void send(AVFrame* frame) {
    check(avcodec_send_frame(codec_, frame), "cannot encode a frame");
    for (;;) {
      const int got = avcodec_receive_packet(codec_, packet_);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "cannot encode a frame");
      av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      check(av_interleaved_write_frame(format_, packet_), "cannot write (disk full?)");
    }
  }

  // Frees everything; before finish() also removes the temporary file.
  void close() {
    sws_freeContext(sws_);
    sws_ = nullptr;
    av_frame_free(&frame_);
    av_packet_free(&packet_);
    avcodec_free_context(&codec_);
    if (format_ != nullptr) {
      if (format_->pb != nullptr) avio_closep(&format_->pb);
      avformat_free_context(format_);
      format_ = nullptr;
    }
    if (!finished_) std::filesystem::remove(temporary_, ignored_);
  }

  std::string path_, temporary_;
  VideoSettings settings_;
  AVFormatContext* format_ = nullptr;
  AVCodecContext* codec_ = nullptr;
  AVStream* stream_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* sws_ = nullptr;
  std::int64_t next_pts_ = 0;
  bool finished_ = false;
  std::error_code ignored_;
};

class FramesFolder final : public FilmWriter {
 public:
  explicit FramesFolder(std::string folder) : folder_(std::move(folder)) {
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    if (error || !std::filesystem::is_directory(folder_))
      throw std::runtime_error(folder_ + ": cannot create the folder" + (error ? ": " + error.message() : ""));
  }
  void add(const scene::RgbaImage& frame) override {
    scene::write_srgb_png(std::filesystem::path(folder_) / fmt::format("frame_{:06d}.png", ++count_), frame);
  }
  void finish() override {}

 private:
  std::string folder_;
  int count_ = 0;
};

}  // namespace

std::optional<VideoCodec> codec_for_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".mp4" || ext == ".m4v" || ext == ".mov") return VideoCodec::h264;
  if (ext == ".webm") return VideoCodec::vp9;
  return std::nullopt;
}

std::unique_ptr<FilmWriter> open_video_file(const std::string& path, const VideoSettings& settings) {
  const auto codec = codec_for_path(path);
  if (!codec) throw std::runtime_error(path + ": a film is written as .mp4 (H.264) or .webm (VP9), or --frames-dir");
  return std::make_unique<VideoFile>(path, *codec, settings);
}

std::unique_ptr<FilmWriter> open_frames_folder(const std::string& folder) {
  return std::make_unique<FramesFolder>(folder);
}

}  // namespace trailray::app
