#include "track/places/place_tags.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <utility>

#include "track/places/place_area.hpp"

namespace trailray::track::places {
namespace {

// Tags by key, the others absent.
PlaceTags tags(std::initializer_list<std::pair<std::string_view, std::string_view>> given) {
  PlaceTags t;
  for (const auto& [key, value] : given) {
    if (key == "name") t.name = value;
    if (key == "natural") t.natural = value;
    if (key == "water") t.water = value;
    if (key == "mountain_pass") t.mountain_pass = value;
    if (key == "tourism") t.tourism = value;
    if (key == "place") t.place = value;
  }
  return t;
}

TEST(PlaceEle, PlainMetres) {
  EXPECT_DOUBLE_EQ(parse_ele("2596"), 2596.0);
  EXPECT_DOUBLE_EQ(parse_ele(" 2637.5 "), 2637.5);
  EXPECT_DOUBLE_EQ(parse_ele("-12"), -12.0);
}

TEST(PlaceEle, DecimalCommaAsAndorraWritesIt) {
  EXPECT_DOUBLE_EQ(parse_ele("3143,45"), 3143.45);
  EXPECT_DOUBLE_EQ(parse_ele("2864,4"), 2864.4);
}

TEST(PlaceEle, MetreUnits) {
  EXPECT_DOUBLE_EQ(parse_ele("2317m"), 2317.0);
  EXPECT_DOUBLE_EQ(parse_ele("2317 m"), 2317.0);
  EXPECT_DOUBLE_EQ(parse_ele("2317 M"), 2317.0);
  EXPECT_DOUBLE_EQ(parse_ele("2317 metres"), 2317.0);
}

TEST(PlaceEle, FeetConverted) {
  EXPECT_NEAR(parse_ele("8000 ft"), 2438.4, 1e-9);
  EXPECT_NEAR(parse_ele("8000ft"), 2438.4, 1e-9);
  EXPECT_NEAR(parse_ele("8000'"), 2438.4, 1e-9);
  EXPECT_NEAR(parse_ele("8000 feet"), 2438.4, 1e-9);
}

TEST(PlaceEle, GarbageIsNaN) {
  for (const char* bad : {"", "  ", "unknown", "2317;2320", "ca. 2300", "2317 km", "m", ",", "-", "1e5", "99999",
                          "2.3.4", "2317 m a.s.l. and more text here beyond reason"})
    EXPECT_TRUE(std::isnan(parse_ele(bad))) << '"' << bad << '"';
}

TEST(PlaceClassifier, NodesByTheirTags) {
  EXPECT_EQ(classify_place(tags({{"name", "Eiger"}, {"natural", "peak"}}), false), PlaceKind::Peak);
  EXPECT_EQ(classify_place(tags({{"name", "Etna"}, {"natural", "volcano"}}), false), PlaceKind::Volcano);
  EXPECT_EQ(classify_place(tags({{"name", "Joch"}, {"natural", "saddle"}}), false), PlaceKind::Saddle);
  // A pass mapped on a saddle node is a pass.
  EXPECT_EQ(classify_place(tags({{"name", "Port"}, {"natural", "saddle"}, {"mountain_pass", "yes"}}), false), PlaceKind::Pass);
  EXPECT_EQ(classify_place(tags({{"name", "Guschg"}, {"tourism", "alpine_hut"}}), false), PlaceKind::AlpineHut);
  EXPECT_EQ(classify_place(tags({{"name", "Biwak"}, {"tourism", "wilderness_hut"}}), false), PlaceKind::WildernessHut);
  EXPECT_EQ(classify_place(tags({{"name", "Vaduz"}, {"place", "town"}}), false), PlaceKind::Town);
  EXPECT_EQ(classify_place(tags({{"name", "Zürich"}, {"place", "city"}}), false), PlaceKind::City);
  EXPECT_EQ(classify_place(tags({{"name", "Planken"}, {"place", "village"}}), false), PlaceKind::Village);
  EXPECT_EQ(classify_place(tags({{"name", "Gaflei"}, {"place", "hamlet"}}), false), PlaceKind::Hamlet);
}

TEST(PlaceClassifier, WithoutANameNothing) {
  EXPECT_FALSE(classify_place(tags({{"natural", "peak"}}), false));
  EXPECT_FALSE(classify_place(tags({{"name", "x"}, {"tourism", "hotel"}}), false));
  EXPECT_FALSE(classify_place(tags({{"name", "x"}, {"place", "locality"}}), false));
}

TEST(PlaceClassifier, LakesButNotRivers) {
  EXPECT_EQ(classify_place(tags({{"name", "Steg"}, {"natural", "water"}, {"water", "reservoir"}}), true), PlaceKind::Lake);
  EXPECT_EQ(classify_place(tags({{"name", "Gänglesee"}, {"natural", "water"}}), true), PlaceKind::Lake);
  EXPECT_EQ(classify_place(tags({{"name", "See"}, {"natural", "water"}, {"water", "lake"}}), false), PlaceKind::Lake);
  EXPECT_FALSE(classify_place(tags({{"name", "Rhein"}, {"natural", "water"}, {"water", "river"}}), true));
  EXPECT_FALSE(classify_place(tags({{"natural", "water"}, {"water", "lake"}}), true));
  // Peaks are nodes: a way tagged natural=peak is not read as one.
  EXPECT_FALSE(classify_place(tags({{"name", "Eiger"}, {"natural", "peak"}}), true));
}

TEST(PlaceArea, GrownByTheMargin) {
  geo::LatLonBounds b;
  b.add(47.0, 9.0);
  b.add(47.1, 9.2);
  const geo::LatLonBounds g = grown_bounds(b, 5000.0);
  EXPECT_NEAR(g.min_lat, 47.0 - 5000.0 / 111320.0, 1e-9);
  EXPECT_NEAR(g.max_lat, 47.1 + 5000.0 / 111320.0, 1e-9);
  // About 5 km of longitude at 47°: 0.066°.
  EXPECT_NEAR(9.0 - g.min_lon, 0.066, 0.002);
  EXPECT_TRUE(contains(g, 47.12, 9.25));
  EXPECT_FALSE(contains(g, 47.2, 9.1));
  EXPECT_TRUE(grown_bounds(geo::LatLonBounds{}, 5000.0).empty());
}

TEST(PlaceMerge, DuplicatesWithinMetresMergedFirstKept) {
  std::vector<Place> places{
      {"Naafkopf", PlaceKind::Peak, 47.0842, 9.6015, 2571.0, 'n', 1},
      {"Naafkopf", PlaceKind::Peak, 47.0842009, 9.6015, 2570.0, 'n', 2},  // 0.1 m north
      {"Naafkopf", PlaceKind::Saddle, 47.0842, 9.6015, NAN, 'n', 3},      // another kind
      {"Other", PlaceKind::Peak, 47.0842, 9.6015, NAN, 'n', 4},           // another name
      {"Naafkopf", PlaceKind::Peak, 47.0852, 9.6015, 2500.0, 'n', 5},     // 111 m away
  };
  merge_duplicate_places(places);
  ASSERT_EQ(places.size(), 4u);
  EXPECT_EQ(places[0].osm_id, 1);
  EXPECT_DOUBLE_EQ(places[0].ele_m, 2571.0);
  EXPECT_EQ(places[1].osm_id, 3);
  EXPECT_EQ(places[3].osm_id, 5);
}

TEST(PlaceMerge, TheKeptOneTakesAnElevationItLacks) {
  std::vector<Place> places{{"A", PlaceKind::Peak, 46.0, 8.0, NAN, 'n', 1},
                            {"A", PlaceKind::Peak, 46.0, 8.00001, 1234.0, 'n', 2}};
  merge_duplicate_places(places);
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0].osm_id, 1);
  EXPECT_DOUBLE_EQ(places[0].ele_m, 1234.0);
}

}  // namespace
}  // namespace trailray::track::places
