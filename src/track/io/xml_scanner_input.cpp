// The scanner's input side: refilling the buffer from the source, counting lines for
// positions, and starting or ending one part of a document.

#include <algorithm>
#include <cstring>
#include <string>

#include "track/io/xml_scanner.hpp"

namespace trailray::track::detail {

SourcePosition XmlScanner::position_of(std::int64_t absolute) {
  // Count newlines between counted_ and `absolute`, as far as they are still in the buffer.
  std::int64_t from = std::max(counted_, base_);
  std::int64_t to = std::min(absolute, abs(end_));
  if (from < to) {
    const char* first = buf_.data() + (from - base_);
    const std::size_t len = static_cast<std::size_t>(to - from);
    // Counted in blocks of 255 with a byte-sized sum, which the compiler vectorises (a plain
    // std::count is not); memrchr finds where the last line starts.
    std::int64_t lines = 0;
    for (std::size_t at = 0; at < len;) {
      const std::size_t block = std::min<std::size_t>(255, len - at);
      unsigned char in_block = 0;
      for (std::size_t k = 0; k < block; ++k) in_block = static_cast<unsigned char>(in_block + (first[at + k] == '\n'));
      lines += in_block;
      at += block;
    }
    if (lines > 0) {
      line_ += lines;
      const char* last_nl = static_cast<const char*>(memrchr(first, '\n', len));
      line_start_ = from + (last_nl - first) + 1;
    }
  }
  counted_ = std::max(counted_, to);
  SourcePosition p;
  p.line = line_;
  p.column = std::max<std::int64_t>(1, absolute - line_start_ + 1);
  p.byte_offset = absolute;
  return p;
}

bool XmlScanner::fill(std::size_t keep_from) {
  if (eof_) return false;
  position_of(abs(keep_from));  // count the lines we are about to drop
  if (!text_owned_ && !text_view_.empty()) materialize_text();
  if (keep_from > 0) {
    std::memmove(buf_.data(), buf_.data() + keep_from, end_ - keep_from);
    base_ += static_cast<std::int64_t>(keep_from);
    end_ -= keep_from;
    pos_ -= std::min(pos_, keep_from);
  }
  if (end_ == buf_.size()) buf_.resize(buf_.size() * 2);
  std::ptrdiff_t n = src_.next(buf_.data() + end_, buf_.size() - end_);
  if (n < 0) {
    read_error_ = true;
    eof_ = true;
    return false;
  }
  if (n == 0) {
    eof_ = true;
    return false;
  }
  end_ += static_cast<std::size_t>(n);
  return true;
}

void XmlScanner::begin_part(const XmlPartStart& start) {
  part_ = true;
  base_ = counted_ = line_start_ = start.byte_offset;
  for (const std::string& name : start.open_elements) {
    starts_.push_back(static_cast<std::uint32_t>(names_.size()));
    locals_.push_back(static_cast<std::uint32_t>(names_.size() + name.size() - xml_local_name(name).size()));
    names_ += name;
  }
  depth_ = static_cast<int>(start.open_elements.size());
  saw_root_ = depth_ > 0;
}

XmlEndState XmlScanner::end_state() {
  XmlEndState e;
  for (std::size_t k = 0; k < starts_.size(); ++k) {
    const std::size_t until = k + 1 < starts_.size() ? starts_[k + 1] : names_.size();
    e.open_elements.emplace_back(names_, starts_[k], until - starts_[k]);
  }
  e.inside_markup = cut_inside_markup_;
  e.end = position_of(abs(end_));
  return e;
}

}  // namespace trailray::track::detail
