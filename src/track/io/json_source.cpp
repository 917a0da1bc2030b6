#include "track/io/json_source.hpp"

#include <algorithm>
#include <cstring>

namespace trailray::track {

std::streambuf::int_type JsonSourceBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (failed_ || at_end_) return traits_type::eof();
  // Retire the chunk: count its line ends once, so positions in later chunks start from here.
  const char* p = buffer_.data();
  const char* end = p + chunk_size_;
  while (const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p))) {
    const char* at = static_cast<const char*>(nl);
    ++lines_before_chunk_;
    line_start_before_chunk_ = chunk_start_ + (at - buffer_.data()) + 1;
    p = at + 1;
  }
  chunk_start_ += chunk_size_;
  chunk_size_ = 0;
  cursor_ = chunk_start_, cursor_lines_ = lines_before_chunk_, cursor_line_start_ = line_start_before_chunk_;
  const std::ptrdiff_t n = source_.next(buffer_.data(), buffer_.size());
  if (n < 0) {
    failed_ = true;
    error_ = source_.error();
    setg(buffer_.data(), buffer_.data(), buffer_.data());
    return traits_type::eof();
  }
  if (n == 0) {
    at_end_ = true;
    setg(buffer_.data(), buffer_.data(), buffer_.data());
    return traits_type::eof();
  }
  chunk_size_ = n;
  setg(buffer_.data(), buffer_.data(), buffer_.data() + n);
  return traits_type::to_int_type(buffer_[0]);
}

SourcePosition JsonSourceBuffer::position_of(std::int64_t offset) {
  offset = std::max<std::int64_t>(offset, 0);
  if (offset < chunk_start_) {
    // Before this chunk (the parser's look-ahead crossed a chunk boundary): its line start.
    return {lines_before_chunk_ + 1, 1, line_start_before_chunk_};
  }
  offset = std::min(offset, chunk_start_ + chunk_size_);
  if (offset < cursor_)
    cursor_ = chunk_start_, cursor_lines_ = lines_before_chunk_, cursor_line_start_ = line_start_before_chunk_;
  for (std::int64_t i = cursor_; i < offset; ++i)
    if (buffer_[static_cast<std::size_t>(i - chunk_start_)] == '\n') ++cursor_lines_, cursor_line_start_ = i + 1;
  cursor_ = offset;
  return {cursor_lines_ + 1, offset - cursor_line_start_ + 1, offset};
}

}  // namespace trailray::track
