#include "scene/pins/place_labels.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/text/label_layout.hpp"
#include "scene/scene.hpp"

namespace trailray::scene {
namespace {

using track::places::Place;
using track::places::PlaceKind;

Place place(const char* name, PlaceKind kind, double ele, double lat = 46.5, double lon = 8.0) {
  Place p;
  p.name = name;
  p.kind = kind;
  p.ele_m = ele;
  p.lat_deg = lat;
  p.lon_deg = lon;
  return p;
}

TEST(PlaceLabels, NamedWithTheirElevationWhereItBelongs) {
  const std::vector<Waypoint> w = osm_place_waypoints(
      {place("Eiger", PlaceKind::Peak, 3967.0), place("Grindelwald", PlaceKind::Village, 1034.0),
       place("Brienzersee", PlaceKind::Lake, 564.0), place("Mittellegi", PlaceKind::AlpineHut, 3355.4),
       place("Nameless ele", PlaceKind::Peak, NAN)},
      "alps.osm.pbf", {});
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w[0].name, "Eiger 3967 m");
  EXPECT_EQ(w[1].name, "Grindelwald");
  EXPECT_EQ(w[2].name, "Brienzersee");
  EXPECT_EQ(w[3].name, "Mittellegi 3355 m");
  EXPECT_EQ(w[4].name, "Nameless ele");
  for (const Waypoint& p : w) {
    EXPECT_EQ(p.kind, WaypointKind::Place);
    EXPECT_EQ(p.source, "alps.osm.pbf");
  }
  // The peak's marker at its summit, the village's on the (neutral) ground.
  EXPECT_NEAR(glm::length(w[0].marker_ecef) - glm::length(w[0].ground_ecef), 3967.0, 1.0);
}

TEST(PlaceLabels, ProminenceDecidesAndHandMadePlacesWin) {
  const auto pri = [](const Place& p) { return osm_place_priority(p); };
  const int eiger = pri(place("Eiger", PlaceKind::Peak, 3967.0));
  const int moench = pri(place("Mönch", PlaceKind::Peak, 4110.0));
  const int unmeasured = pri(place("Hoger", PlaceKind::Peak, NAN));
  const int city = pri(place("Bern", PlaceKind::City, 540.0));
  const int town = pri(place("Interlaken", PlaceKind::Town, 566.0));
  const int lake = pri(place("Brienzersee", PlaceKind::Lake, 564.0));
  const int pass = pri(place("Grimselpass", PlaceKind::Pass, 2164.0));
  const int saddle = pri(place("Joch", PlaceKind::Saddle, 3000.0));
  const int hut = pri(place("Hütte", PlaceKind::AlpineHut, 3355.0));
  const int village = pri(place("Grindelwald", PlaceKind::Village, 1034.0));
  const int hamlet = pri(place("Bort", PlaceKind::Hamlet, 1570.0));
  EXPECT_GT(moench, eiger);
  EXPECT_GT(eiger, unmeasured);
  EXPECT_GT(city, moench);
  EXPECT_GT(unmeasured, town);
  EXPECT_GT(town, lake);
  EXPECT_GT(lake, saddle);
  EXPECT_GT(saddle, pass);
  EXPECT_GT(pass, hut);
  EXPECT_GT(hut, village);
  EXPECT_GT(village, hamlet);
  EXPECT_LT(city, kPlacePriority);  // a --labels place wins over every one of them
  // The highest on Earth stays inside its band.
  EXPECT_LT(pri(place("Everest", PlaceKind::Peak, 8849.0)), city);
}

TEST(PlaceLabels, AreLabelCandidatesOfKindPlace) {
  WaypointSet set;
  set.points = osm_place_waypoints({place("Eiger", PlaceKind::Peak, 3967.0)}, "alps.osm", {});
  Scene scene;
  scene.waypoints = &set;
  const std::vector<LabelCandidate> c = label_candidates(scene);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].text, "Eiger 3967 m");
  EXPECT_EQ(c[0].kind, LabelKind::place);
  EXPECT_EQ(c[0].priority, osm_place_priority(place("Eiger", PlaceKind::Peak, 3967.0)));
}

}  // namespace
}  // namespace trailray::scene
