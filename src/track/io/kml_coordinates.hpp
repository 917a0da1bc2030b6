#pragma once
// A KML <coordinates> text read in pieces as the scanner streams it (XmlHandler::stream_text):
// tuples are handed out as soon as they are complete, so a LineString of any length is read
// without holding its text, each tuple with the line and column it starts at.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/io/kml_values.hpp"

namespace trailray::track {

class CoordinatesStream {
 public:
  using TupleHandler = std::function<void(const KmlTuple&, const SourcePosition&)>;

  // A new <coordinates> element at `element` (its '<').
  void begin(const SourcePosition& element);
  // The next piece of its text; complete tuples go to `on_tuple`.
  void feed(std::string_view piece, const TupleHandler& on_tuple);
  // At the element's end: the tuples left.
  void finish(const TupleHandler& on_tuple);
  // At a cut inside the element: the tuples left but the last, which may be incomplete.
  void finish_cut(const TupleHandler& on_tuple);

 private:
  void emit(std::size_t length, const TupleHandler& on_tuple);  // the tuples in carry_[0, length)
  std::size_t complete_prefix() const;                          // where carry_ may be cut

  std::string carry_;  // text not yet handed out
  SourcePosition element_;
  std::int64_t lines_ = 0;    // newlines handed out before carry_
  std::int64_t column_ = -1;  // 0-based column of carry_[0]; -1 while on the element's line
  std::vector<KmlTuple> tuples_;
};

}  // namespace trailray::track
