#include "app/flight/check_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ctime>

namespace trailray::app {
namespace {

using track::airspace::Airspace;
using track::airspace::Infringement;

std::string iso_time(double t) {
  if (std::isnan(t)) return "";
  const std::time_t s = static_cast<std::time_t>(std::floor(t));
  std::tm tm{};
  gmtime_r(&s, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S", &tm);
  return fmt::format("{}.{:01d}Z", buffer, static_cast<int>((t - std::floor(t)) * 10.0));
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(std::round(v * 10) / 10) : nullptr; }

nlohmann::json limit_json(const track::airspace::AltitudeLimit& l) {
  static const char* refs[] = {"MSL", "AGL", "STD", "UNL"};
  return {{"text", l.text},
          {"reference", refs[static_cast<int>(l.reference)]},
          {"metres", l.reference == track::airspace::AltitudeReference::Unlimited ? nlohmann::json(nullptr)
                                                                                  : number_or_null(l.metres)}};
}

nlohmann::json time_json(double t) { return std::isnan(t) ? nlohmann::json(nullptr) : nlohmann::json(iso_time(t)); }

std::string metres(double v) { return std::isfinite(v) ? fmt::format("{:.0f} m", v) : "?"; }

}  // namespace

std::size_t CheckReport::total() const {
  std::size_t n = 0;
  for (const auto& t : tracks) n += t.infringements.size();
  return n;
}

nlohmann::json check_json(const CheckReport& report) {
  nlohmann::json tracks = nlohmann::json::array();
  for (const auto& t : report.tracks) {
    nlohmann::json list = nlohmann::json::array();
    for (const Infringement& f : t.infringements) {
      const Airspace& a = report.airspaces->airspaces[f.airspace];
      list.push_back(nlohmann::json{{"airspace", a.name},
                                    {"class", a.airspace_class},
                                    {"line", a.line},
                                    {"floor", limit_json(a.floor)},
                                    {"ceiling", limit_json(a.ceiling)},
                                    {"segment", f.segment},
                                    {"first_point", f.first_point},
                                    {"last_point", f.last_point},
                                    {"entry_time", time_json(f.entry_time)},
                                    {"exit_time", time_json(f.exit_time)},
                                    {"duration_s", number_or_null(f.exit_time - f.entry_time)},
                                    {"inside_at_start", f.inside_at_start},
                                    {"inside_at_end", f.inside_at_end},
                                    {"max_horizontal_m", number_or_null(f.max_horizontal_m)},
                                    {"max_above_floor_m", number_or_null(f.max_above_floor_m)},
                                    {"max_below_ceiling_m", number_or_null(f.max_below_ceiling_m)},
                                    {"max_vertical_m", number_or_null(f.max_vertical_m)},
                                    {"floor_altitude", f.floor_altitude},
                                    {"ceiling_altitude", f.ceiling_altitude},
                                    {"ground_assumed", f.ground_assumed}});
    }
    tracks.push_back(
        nlohmann::json{{"path", t.path}, {"points", t.points}, {"altitudes", t.altitudes}, {"infringements", list}});
  }
  return nlohmann::json{{"airspace_file", report.airspace_path},
                        {"airspaces", report.airspaces->airspaces.size()},
                        {"terrain", report.terrain},
                        {"infringements", report.total()},
                        {"tracks", tracks}};
}

std::string check_text(const CheckReport& report) {
  std::string out;
  for (const auto& t : report.tracks) {
    out += fmt::format("{}: {} infringement{} ({} points; {})\n", t.path, t.infringements.size(),
                       t.infringements.size() == 1 ? "" : "s", t.points, t.altitudes);
    for (const Infringement& f : t.infringements) {
      const Airspace& a = report.airspaces->airspaces[f.airspace];
      out +=
          fmt::format("  {} [{}] {} .. {}: {} - {} ({:.0f} s){}{}\n", a.name, a.airspace_class, a.floor.text,
                      a.ceiling.text, std::isnan(f.entry_time) ? "?" : iso_time(f.entry_time).substr(11),
                      std::isnan(f.exit_time) ? "?" : iso_time(f.exit_time).substr(11),
                      std::isnan(f.exit_time - f.entry_time) ? 0.0 : f.exit_time - f.entry_time,
                      f.inside_at_start ? ", inside from the start" : "", f.inside_at_end ? ", inside at the end" : "");
      out += fmt::format("    {} inside the boundary, {} above the floor ({}), {} below the ceiling ({}){}\n",
                         metres(f.max_horizontal_m), metres(f.max_above_floor_m), f.floor_altitude,
                         metres(f.max_below_ceiling_m), f.ceiling_altitude,
                         f.ground_assumed ? "; ground unknown: AGL limits taken conservatively" : "");
    }
  }
  out += fmt::format("{} infringement{} in {} track{} against {} airspaces of {}\n", report.total(),
                     report.total() == 1 ? "" : "s", report.tracks.size(), report.tracks.size() == 1 ? "" : "s",
                     report.airspaces->airspaces.size(), report.airspace_path);
  return out;
}

}  // namespace trailray::app
