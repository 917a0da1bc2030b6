#include "track/io/kml_coordinates.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kBatch = 64 << 10;  // text gathered before tuples are split off
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

void CoordinatesStream::begin(const SourcePosition& element) {
  carry_.clear();
  element_ = element;
  lines_ = 0;
  column_ = -1;
}

void CoordinatesStream::feed(std::string_view piece, const TupleHandler& on_tuple) {
  carry_.append(piece);
  if (carry_.size() < kBatch) return;
  std::size_t cut = complete_prefix();
  // No place to cut in this much text: one monstrous tuple, unreadable however it is cut.
  if (cut == 0 && carry_.size() > 16 * kBatch) cut = carry_.size();
  if (cut > 0) emit(cut, on_tuple);
}

void CoordinatesStream::finish(const TupleHandler& on_tuple) { emit(carry_.size(), on_tuple); }

void CoordinatesStream::finish_cut(const TupleHandler& on_tuple) { emit(complete_prefix(), on_tuple); }

// The start of the last tuple that may still grow: after the last whitespace that separates two
// tuples (not next to a comma, which would continue the tuple). 0 when there is none.
std::size_t CoordinatesStream::complete_prefix() const {
  std::size_t i = carry_.size();
  while (i > 0) {
    // Skip the (possibly incomplete) last token, then find the whitespace before it.
    while (i > 0 && !is_space(carry_[i - 1])) --i;
    const std::size_t next = i;  // first character after the whitespace
    while (i > 0 && is_space(carry_[i - 1])) --i;
    if (i == 0 || next == carry_.size()) continue;
    if (carry_[i - 1] != ',' && carry_[next] != ',') return next;
  }
  return 0;
}

void CoordinatesStream::emit(std::size_t length, const TupleHandler& on_tuple) {
  const std::string_view text(carry_.data(), length);
  tuples_.clear();
  split_kml_tuples(text, tuples_);
  std::size_t counted = 0;  // text scanned for newlines so far
  std::int64_t lines = lines_, column = column_;
  for (const KmlTuple& t : tuples_) {
    for (; counted < t.offset; ++counted) {
      if (text[counted] == '\n') {
        ++lines;
        column = 0;
      } else if (column >= 0) {
        ++column;
      }
    }
    SourcePosition p = element_;
    p.byte_offset = -1;
    p.line += lines;
    if (column >= 0) p.column = column + 1;  // else the element's column: the best known
    on_tuple(t, p);
  }
  for (; counted < length; ++counted) {
    if (text[counted] == '\n') {
      ++lines;
      column = 0;
    } else if (column >= 0) {
      ++column;
    }
  }
  lines_ = lines;
  column_ = column;
  carry_.erase(0, length);
}

}  // namespace trailray::track
