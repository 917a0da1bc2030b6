#pragma once
// A ByteSource as a std::streambuf for nlohmann's SAX parser, which reads it one byte at a time
// (sbumpc). Keeps what a reader needs to say where something is: bytes consumed so far, and the
// line and column of a byte offset, computed on demand by counting line ends forward from the
// last offset asked for (the parser's events only move forward), so positions cost O(file)
// in all, without keeping the file.

#include <array>
#include <cstdint>
#include <streambuf>
#include <string>

#include "track/diagnostics.hpp"
#include "track/io/byte_source.hpp"

namespace trailray::track {

class JsonSourceBuffer final : public std::streambuf {
 public:
  explicit JsonSourceBuffer(ByteSource& source) : source_(source) {}

  // Bytes handed to the parser so far.
  std::int64_t consumed() const { return chunk_start_ + (gptr() - eback()); }
  // The offset of the byte the parser read last (the one that completed the current event).
  std::int64_t last_offset() const { return consumed() > 0 ? consumed() - 1 : 0; }
  // Line and column (1-based, columns in bytes) of `offset`; exact for offsets in the current
  // chunk or later than the last one asked for, else the line start of the chunk (never wrong by
  // more than the chunk).
  SourcePosition position_of(std::int64_t offset);
  SourcePosition here() { return position_of(last_offset()); }

  bool read_failed() const { return failed_; }
  bool at_end() const { return at_end_; }
  const std::string& read_error() const { return error_; }

 protected:
  int_type underflow() override;

 private:
  static constexpr std::size_t kChunk = 64 * 1024;

  ByteSource& source_;
  std::array<char, kChunk> buffer_{};
  std::int64_t chunk_start_ = 0;  // offset of buffer_[0]
  std::int64_t chunk_size_ = 0;
  // Lines counted over [0, chunk_start_): the chunks already handed out.
  std::int64_t lines_before_chunk_ = 0;       // line ends before the chunk
  std::int64_t line_start_before_chunk_ = 0;  // offset just after the last line end before it
  // The forward cursor inside the current chunk.
  std::int64_t cursor_ = 0, cursor_lines_ = 0, cursor_line_start_ = 0;
  bool failed_ = false, at_end_ = false;
  std::string error_;
};

}  // namespace trailray::track
