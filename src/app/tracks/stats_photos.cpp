#include "app/tracks/stats_photos.hpp"

#include <fmt/format.h>

#include <cmath>

#include "track/io/text_output.hpp"

namespace trailray::app {
namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json placed_photos_json(const track::PhotoPlacement& placement) {
  nlohmann::json out = nlohmann::json::array();
  for (const track::PlacedPhoto& p : placement.placed) {
    out.push_back({{"path", track::valid_utf8(p.photo.path)},
                   {"lat", p.lat_deg},
                   {"lon", p.lon_deg},
                   {"ele", number_or_null(p.ele_m)},
                   {"time", std::isfinite(p.time_unix_s) ? nlohmann::json(track::format_iso_time(p.time_unix_s))
                                                          : nlohmann::json(nullptr)},
                   {"placed_by", p.placed_by == track::PhotoPlacedBy::gps ? "gps" : "time"},
                   {"track", p.track},
                   {"distance_m", p.distance_m},
                   {"gps_offset_m", number_or_null(p.gps_offset_m)}});
  }
  return out;
}

std::string placed_photos_lines(const track::PhotoPlacement& placement, std::size_t photo_count,
                                const std::vector<std::string>& track_names) {
  std::string out =
      fmt::format("  photos: {} of {} placed on this file's tracks\n", placement.placed.size(), photo_count);
  for (const track::PlacedPhoto& p : placement.placed) {
    const std::string track = p.track < track_names.size() ? track_names[p.track] : fmt::format("#{}", p.track + 1);
    const std::string how = p.placed_by == track::PhotoPlacedBy::gps
                                ? fmt::format("by GPS, {:.0f} m from its position", p.gps_offset_m)
                                : "by time";
    out += fmt::format("    {}  {}  {:.3f} km  {}  {}\n", p.photo.path, track, p.distance_m / 1000.0,
                       std::isfinite(p.time_unix_s) ? track::format_iso_time(p.time_unix_s) : "-", how);
  }
  return out;
}

void UnplacedPhotos::add_file(const track::PhotoPlacement& placement) {
  ++files_;
  for (std::size_t k : placement.placed_photo)
    if (k < placed_.size()) placed_[k] = true;
  for (const track::UnplacedPhoto& u : placement.unplaced) {
    if (u.photo >= reasons_.size()) continue;
    const std::string reason = u.reason.to_string();
    if (!reasons_[u.photo])
      reasons_[u.photo] = reason;
    else if (*reasons_[u.photo] != reason)
      differ_[u.photo] = true;
  }
}

void UnplacedPhotos::report(const std::vector<track::PhotoMetadata>& photos, scene::Diagnostics& diagnostics) const {
  for (std::size_t k = 0; k < placed_.size() && k < photos.size(); ++k) {
    if (placed_[k]) continue;
    if (reasons_[k] && !differ_[k])
      diagnostics.warning(*reasons_[k]);
    else
      diagnostics.warning(fmt::format("{}: not placed: not within 100 m of a track of the {} files, nor taken within "
                                      "their times",
                                      photos[k].path, files_));
  }
}

}  // namespace trailray::app
