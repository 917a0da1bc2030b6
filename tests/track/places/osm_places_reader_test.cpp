#include "track/places/osm_places_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "test_support.hpp"
#include "track/places/place_area.hpp"

namespace trailray::track::places {
namespace {

std::map<PlaceKind, int> count_kinds(const std::vector<Place>& places) {
  std::map<PlaceKind, int> n;
  for (const Place& p : places) ++n[p.kind];
  return n;
}

int count_with_ele(const std::vector<Place>& places, PlaceKind kind) {
  return static_cast<int>(std::count_if(places.begin(), places.end(),
                                        [&](const Place& p) { return p.kind == kind && !std::isnan(p.ele_m); }));
}

const Place* find(const std::vector<Place>& places, const std::string& name, PlaceKind kind) {
  for (const Place& p : places)
    if (p.name == name && p.kind == kind) return &p;
  return nullptr;
}

const Place* highest_peak(const std::vector<Place>& places) {
  const Place* best = nullptr;
  for (const Place& p : places)
    if (p.kind == PlaceKind::Peak && !std::isnan(p.ele_m) && (best == nullptr || p.ele_m > best->ele_m)) best = &p;
  return best;
}

// MANIFEST.md: 106 natural=peak nodes (3 without a name, so no label), 98 with name and ele; 11
// alpine huts (nodes; the hut mapped as a way is no hut here), 17 passes, no saddle.
TEST(OsmPlaces, AndorraCountsAndItsMessyEle) {
  TRAILRAY_REQUIRE_DATA(path, "osm/graphhopper_andorra.osm.pbf");
  const std::vector<Place> places = read_osm_places(path.string());
  std::map<PlaceKind, int> n = count_kinds(places);
  EXPECT_EQ(n[PlaceKind::Peak], 103);
  EXPECT_EQ(count_with_ele(places, PlaceKind::Peak), 98);
  EXPECT_EQ(n[PlaceKind::AlpineHut], 11);
  EXPECT_EQ(n[PlaceKind::Pass], 17);
  EXPECT_EQ(n[PlaceKind::Saddle], 0);
  EXPECT_EQ(n[PlaceKind::Village], 32);
  EXPECT_EQ(n[PlaceKind::Town], 7);
  // The highest peak's ele is "3143,45": a decimal comma.
  const Place* top = highest_peak(places);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->name, "Pica d'Estats");
  EXPECT_DOUBLE_EQ(top->ele_m, 3143.45);
  // "2317m": a unit.
  const Place* carroi = find(places, "Pic Carroi", PlaceKind::Peak);
  ASSERT_NE(carroi, nullptr);
  EXPECT_DOUBLE_EQ(carroi->ele_m, 2317.0);
  const Place* envalira = find(places, "Port d'Envalira", PlaceKind::Pass);
  ASSERT_NE(envalira, nullptr);
  EXPECT_NEAR(envalira->ele_m, 2408.0, 0.5);
  for (const Place& p : places) {
    EXPECT_FALSE(p.name.empty());
    EXPECT_GT(p.lat_deg, 41.7);
    EXPECT_LT(p.lat_deg, 42.8);
  }
}

// MANIFEST.md: 12 peaks with ele, Naafkopf twice (2571 and 2570 m, 0.1 m apart): merged into one.
TEST(OsmPlaces, Liechtenstein2013DuplicatePeakMerged) {
  TRAILRAY_REQUIRE_DATA(path, "osm/osm2pgsql_liechtenstein-2013-08-03.osm.pbf");
  const std::vector<Place> places = read_osm_places(path.string());
  std::map<PlaceKind, int> n = count_kinds(places);
  EXPECT_EQ(n[PlaceKind::Peak], 11);
  EXPECT_EQ(count_with_ele(places, PlaceKind::Peak), 11);
  EXPECT_EQ(std::count_if(places.begin(), places.end(), [](const Place& p) { return p.name == "Naafkopf"; }), 1);
  EXPECT_EQ(n[PlaceKind::AlpineHut], 1);
  const Place* guschg = find(places, "Guschg", PlaceKind::AlpineHut);
  ASSERT_NE(guschg, nullptr);
  EXPECT_TRUE(std::isnan(guschg->ele_m));  // the hut has no ele
  const Place* top = highest_peak(places);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->name, "Vorder Grauspitz");
  EXPECT_DOUBLE_EQ(top->ele_m, 2599.0);
}

// Two disjoint areas in one file (Liechtenstein and Autauga County, Alabama): the area filter keeps
// one. MANIFEST.md: 49 peaks (44 with name and ele), 8 saddles (4 of them passes), one alpine hut.
TEST(OsmPlaces, NominatimTwoAreasAndTheAreaFilter) {
  TRAILRAY_REQUIRE_DATA(path, "osm/nominatim_apidb-test-data.pbf");
  const std::vector<Place> all = read_osm_places(path.string());
  std::map<PlaceKind, int> n = count_kinds(all);
  EXPECT_EQ(n[PlaceKind::Peak], 47);  // two of the 49 have no name
  EXPECT_EQ(count_with_ele(all, PlaceKind::Peak), 44);
  EXPECT_EQ(n[PlaceKind::Saddle], 4);
  EXPECT_EQ(n[PlaceKind::Pass], 2);
  EXPECT_EQ(n[PlaceKind::AlpineHut], 1);
  const bool has_alabama =
      std::any_of(all.begin(), all.end(), [](const Place& p) { return p.lon_deg < -80.0; });
  EXPECT_TRUE(has_alabama);

  geo::LatLonBounds liechtenstein;
  liechtenstein.add(47.04, 9.47);
  liechtenstein.add(47.27, 9.64);
  const std::vector<Place> kept = read_osm_places(path.string(), {liechtenstein});
  EXPECT_LT(kept.size(), all.size());
  EXPECT_FALSE(kept.empty());
  for (const Place& p : kept) EXPECT_TRUE(contains(liechtenstein, p.lat_deg, p.lon_deg)) << p.name;
  const Place* grauspitz = find(kept, "Vorder Grauspitz", PlaceKind::Peak);
  ASSERT_NE(grauspitz, nullptr);
  EXPECT_DOUBLE_EQ(grauspitz->ele_m, 2599.0);
  // Named lakes are areas: Gänglesee is a way in Liechtenstein, labelled at its ring's mean.
  std::map<PlaceKind, int> k = count_kinds(kept);
  EXPECT_GT(k[PlaceKind::Lake], 0);
  for (const Place& p : kept) {
    if (p.kind == PlaceKind::Lake) {
      EXPECT_NE(p.osm_type, 'n') << p.name;
    }
  }
}

// Gzipped XML whose <bounds> lie (it claims 11.328-11.334 E; the nodes span 11.298-11.498 E): the
// nodes are read, not the header. MANIFEST.md: 24 peaks (23 with name and ele), Kleiner Solstein
// 2637 m the highest.
TEST(OsmPlaces, HoheWarteGzXmlWithLyingBounds) {
  TRAILRAY_REQUIRE_DATA(path, "osm/graphhopper_hohe-warte.osm.gz");
  const std::vector<Place> places = read_osm_places(path.string());
  EXPECT_EQ(count_kinds(places)[PlaceKind::Peak], 23);
  EXPECT_EQ(count_with_ele(places, PlaceKind::Peak), 23);
  EXPECT_EQ(count_kinds(places)[PlaceKind::Pass], 6);
  const Place* top = highest_peak(places);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->name, "Kleiner Solstein");
  EXPECT_DOUBLE_EQ(top->ele_m, 2637.0);
  const double east = std::max_element(places.begin(), places.end(), [](const Place& a, const Place& b) {
                        return a.lon_deg < b.lon_deg;
                      })->lon_deg;
  EXPECT_GT(east, 11.4);  // far outside the header's bounds
}

TEST(OsmPlaces, XmlFromMemoryWithBadElementsSkipped) {
  const std::string xml = R"(<?xml version="1.0" encoding="UTF-8"?>
<osm version="0.6" generator="test">
 <node id="1" lat="46.5" lon="8.0"><tag k="natural" v="peak"/><tag k="name" v="Eiger"/><tag k="ele" v="3967"/></node>
 <node id="2" lat="46.6" lon="8.1"><tag k="natural" v="peak"/><tag k="ele" v="4000"/></node>
 <node id="3" lat="46.7" lon="8.2"><tag k="natural" v="peak"/><tag k="name" v="Odd"/><tag k="ele" v="high"/></node>
 <node id="4" lat="95.0" lon="8.2"><tag k="natural" v="peak"/><tag k="name" v="Off the Earth"/></node>
 <node id="5" lat="46.0" lon="8.0"/>
 <node id="6" lat="46.0" lon="8.2"/>
 <node id="7" lat="46.2" lon="8.2"/>
 <node id="8" lat="46.2" lon="8.0"/>
 <node id="9" lat="45.0" lon="7.0"><tag k="place" v="village"/><tag k="name" v="Far"/></node>
 <way id="10"><nd ref="5"/><nd ref="6"/><nd ref="7"/><nd ref="8"/><nd ref="5"/>
  <tag k="natural" v="water"/><tag k="name" v="Square Lake"/></way>
 <way id="11"><nd ref="5"/><nd ref="6"/><tag k="natural" v="water"/><tag k="water" v="river"/><tag k="name" v="Aare"/></way>
</osm>)";
  const std::vector<Place> all = read_osm_places_from_memory(xml, "osm", "test.osm");
  ASSERT_EQ(all.size(), 4u);  // Eiger, Odd, Far, Square Lake
  EXPECT_EQ(all[0].name, "Eiger");
  EXPECT_DOUBLE_EQ(all[0].ele_m, 3967.0);
  EXPECT_EQ(all[1].name, "Odd");
  EXPECT_TRUE(std::isnan(all[1].ele_m));
  EXPECT_EQ(all[3].name, "Square Lake");
  EXPECT_EQ(all[3].kind, PlaceKind::Lake);
  EXPECT_NEAR(all[3].lat_deg, 46.1, 1e-9);  // the closing node counted once
  EXPECT_NEAR(all[3].lon_deg, 8.1, 1e-9);

  geo::LatLonBounds area;
  area.add(45.9, 7.9);
  area.add(46.6, 8.3);
  const std::vector<Place> kept = read_osm_places_from_memory(xml, "osm", "test.osm", {area});
  ASSERT_EQ(kept.size(), 2u);  // Eiger and the lake (its label point inside)
  EXPECT_EQ(kept[0].name, "Eiger");
  EXPECT_EQ(kept[1].name, "Square Lake");
}

TEST(OsmPlaces, AFileThatCannotBeReadIsAnErrorNamingIt) {
  try {
    read_osm_places("/nonexistent/alps.osm.pbf");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/alps.osm.pbf"), std::string::npos) << e.what();
  }
  test::TempFile broken("broken.osm.pbf", std::string("\0\0\0\x0dnot a pbf at all, just some words", 37));
  try {
    read_osm_places(broken.str());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.osm.pbf"), std::string::npos) << e.what();
  }
  test::TempFile truncated("cut.osm", "<?xml version='1.0'?><osm version='0.6'><node id='1' lat='4");
  EXPECT_THROW(read_osm_places(truncated.str()), std::runtime_error);
}

}  // namespace
}  // namespace trailray::track::places
