#include "app/options/places_options.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>

#include "track/places/osm_places_reader.hpp"
#include "track/places/place_area.hpp"

namespace trailray::app {

void add_places_option(CLI::App& command, std::string& file, PlacesUse use) {
  const char* what =
      use == PlacesUse::visits
          ? "Places from an OpenStreetMap file (.osm.pbf, .osm, .osm.gz, .osm.bz2): each track lists the summits it "
            "reached (natural=peak or volcano passed within 50 m and no more than 30 m below its ele; its position "
            "alone without elevations) and the huts it passed (alpine or wilderness hut within 50 m), with the times"
          : "Places from an OpenStreetMap file (.osm.pbf, .osm, .osm.gz, .osm.bz2) labelled around the tracks (their "
            "bounds and 5 km): peaks and volcanoes with their ele ('Eiger 3967 m'), saddles, passes, huts, cities, "
            "towns, villages, hamlets and named lakes; the higher peaks and larger places win where labels collide";
  command.add_option("--places", file, what)->type_name("FILE")->check(CLI::ExistingFile);
}

std::vector<track::places::Place> visit_places(std::vector<track::places::Place> places) {
  std::erase_if(places, [](const track::places::Place& p) {
    return !track::places::is_summit(p.kind) && !track::places::is_hut(p.kind);
  });
  return places;
}

std::vector<track::places::Place> read_visit_places(const std::string& file) {
  return visit_places(track::places::read_osm_places(file));
}

std::vector<track::places::Place> read_label_places(const std::string& file, const geo::LatLonBounds& bounds) {
  track::places::PlacesReadOptions options;
  if (!bounds.empty()) options.area = track::places::grown_bounds(bounds, kPlacesMarginM);
  return track::places::read_osm_places(file, options);
}

}  // namespace trailray::app
