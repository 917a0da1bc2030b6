#pragma once
// Reads a track file's bytes in chunks: a path or "-" for standard input, gzip-compressed or
// not (zlib passes plain files through). The input is only ever opened for reading.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace trailray::track {

class ByteSource {
 public:
  // Opens `path` ("-" = standard input). On failure returns nullptr and sets `error`.
  static std::unique_ptr<ByteSource> open(const std::string& path, std::string& error);
  // A source over bytes in memory (tests, fuzzers). Gzip is detected here too.
  static std::unique_ptr<ByteSource> from_memory(std::string data, std::string display_name);

  virtual ~ByteSource() = default;

  // Up to `max` bytes into `out`; 0 at end of input; -1 on a read error (see error()).
  virtual std::ptrdiff_t read(char* out, std::size_t max) = 0;
  virtual std::string error() const = 0;

  // Random access, for reading a big file in parts: the total size in bytes (-1 when the
  // source is a stream or compressed), and an independent source over [begin, end).
  virtual std::int64_t size() const { return -1; }
  virtual std::unique_ptr<ByteSource> range(std::int64_t /*begin*/, std::int64_t /*end*/) const { return nullptr; }

  // The first bytes of the (decompressed) input, without consuming them.
  std::string_view peek(std::size_t n);
  // read() including any peeked bytes.
  std::ptrdiff_t next(char* out, std::size_t max);

  const std::string& display_name() const { return name_; }
  const std::string& path() const { return path_; }

 protected:
  ByteSource(std::string path, std::string name) : path_(std::move(path)), name_(std::move(name)) {}

 private:
  std::string path_;
  std::string name_;
  std::string peeked_;
  std::size_t peeked_pos_ = 0;
};

// Splits a ByteSource into lines ("\n", "\r\n" or "\r" endings), tracking line numbers and
// byte offsets. Lines longer than `max_line` are cut and flagged.
class LineReader {
 public:
  explicit LineReader(ByteSource& src, std::size_t max_line = 1 << 20) : src_(src), max_line_(max_line) {}

  // The next line without its ending; false at end of input.
  bool next(std::string_view& line);
  std::int64_t line_number() const { return line_no_; }
  std::int64_t line_offset() const { return line_offset_; }      // byte offset of the line start
  bool last_line_cut() const { return cut_; }                    // longer than max_line
  bool last_line_unterminated() const { return unterminated_; }  // no line ending (file cut?)
  bool read_failed() const { return failed_; }

 private:
  bool fill();

  ByteSource& src_;
  std::size_t max_line_;
  std::string buf_;
  std::size_t pos_ = 0;
  bool eof_ = false;
  bool failed_ = false;
  bool cut_ = false;
  bool unterminated_ = false;
  std::string current_;
  std::int64_t line_no_ = 0;
  std::int64_t consumed_ = 0;  // bytes consumed before buf_[0]
  std::int64_t line_offset_ = 0;
};

}  // namespace trailray::track
