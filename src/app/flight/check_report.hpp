#pragma once
// The output of `trailray check`: a short text per track, or one JSON document.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "track/airspace/airspace.hpp"
#include "track/airspace/infringement.hpp"

namespace trailray::app {

struct CheckedTrack {
  std::string path;
  std::size_t points = 0;
  std::string altitudes;  // how the track's altitudes were taken, in words
  std::vector<track::airspace::Infringement> infringements;
};

struct CheckReport {
  std::string airspace_path;
  const track::airspace::AirspaceFile* airspaces = nullptr;
  bool terrain = false;  // ground heights from --terrain
  std::vector<CheckedTrack> tracks;
  std::size_t total() const;
};

nlohmann::json check_json(const CheckReport& report);
std::string check_text(const CheckReport& report);

}  // namespace trailray::app
