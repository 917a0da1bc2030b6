// CoordinatesStream: the same tuples at the same positions whatever pieces the text comes in.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "track/io/kml_coordinates.hpp"

using namespace trailray::track;

namespace {

struct Seen {
  std::string text;
  bool readable;
  std::int64_t line, column;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> read_in_pieces(const std::string& text, std::size_t max_piece, unsigned seed, bool cut = false) {
  std::vector<Seen> seen;
  CoordinatesStream s;
  s.begin(SourcePosition{10, 7, 300});
  auto on = [&](const KmlTuple& t, const SourcePosition& p) {
    seen.push_back({std::string(t.text), t.value.has_value(), p.line, p.column});
  };
  std::mt19937 rng(seed);
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t n = std::min<std::size_t>(text.size() - at, 1 + rng() % max_piece);
    s.feed(std::string_view(text).substr(at, n), on);
    at += n;
  }
  if (cut)
    s.finish_cut(on);
  else
    s.finish(on);
  return seen;
}

}  // namespace

TEST(KmlCoordinatesStream, PiecesDoNotChangeTuplesOrPositions) {
  std::string text = " 1,2,3 4 , 5\n";
  for (int i = 0; i < 20000; ++i) text += (i % 997 == 0 ? "x," : "") + std::to_string(i) + ",1,2 \t";
  text += "\n  7,8\r\n";
  const std::vector<Seen> whole = read_in_pieces(text, text.size(), 1);
  ASSERT_EQ(whole.size(), 20003u);
  EXPECT_EQ(whole[0], (Seen{"1,2,3", true, 10, 7}));  // on the element's line: its column
  EXPECT_EQ(whole[1], (Seen{"4 , 5", true, 10, 7}));
  EXPECT_EQ(whole[2], (Seen{"x,0,1,2", false, 11, 1}));  // four components
  EXPECT_EQ(whole.back(), (Seen{"7,8", true, 12, 3}));
  for (std::size_t max_piece : {1u, 2u, 7u, 100u, 70000u})
    EXPECT_EQ(read_in_pieces(text, max_piece, static_cast<unsigned>(max_piece)), whole) << max_piece;
}

TEST(KmlCoordinatesStream, ACutKeepsAllButThePossiblyIncompleteLastTuple) {
  EXPECT_EQ(read_in_pieces("1,1 2,2 3.", 3, 5, true).size(), 2u);
  EXPECT_EQ(read_in_pieces("1,1 2,2 ", 3, 5, true).size(), 1u);  // "2,2" might have gone on ",5"
  EXPECT_TRUE(read_in_pieces("1,1", 3, 5, true).empty());
}
