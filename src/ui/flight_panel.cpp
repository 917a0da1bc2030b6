#include "ui/flight_panel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "scene/pins/thermal_markers.hpp"

namespace trailray::ui {
namespace {

namespace fl = track::flight;

std::string utc_clock(double unix_s) {
  if (!std::isfinite(unix_s)) return "--:--:--";
  const auto t = static_cast<std::time_t>(std::floor(unix_s));
  std::tm tm{};
  gmtime_r(&t, &tm);
  return fmt::format("{:02}:{:02}:{:02}", tm.tm_hour, tm.tm_min, tm.tm_sec);
}

std::string duration(double s) {
  if (!std::isfinite(s) || s < 0) return "-";
  const long total = std::lround(s);
  return fmt::format("{}:{:02}:{:02}", total / 3600, (total / 60) % 60, total % 60);
}

std::string minutes(double s) { return fmt::format("{:.0f} min", s / 60.0); }

std::string climb(double ms) { return std::isfinite(ms) ? fmt::format("{:+.1f} m/s", ms) : "-"; }

std::string metres(double m) { return std::isfinite(m) ? fmt::format("{:.0f} m", m) : "-"; }

}  // namespace

std::vector<std::string> flight_summary_lines(const fl::Flight& f) {
  std::vector<std::string> out;
  out.push_back(fmt::format("take-off {} UTC, {}", utc_clock(f.takeoff.time), metres(f.takeoff.alt)));
  out.push_back(fmt::format("landing {} UTC, {}", utc_clock(f.landing.time), metres(f.landing.alt)));
  out.push_back(fmt::format("duration {}, {:.1f} km", duration(f.duration_s), f.distance_m / 1000.0));
  out.push_back(fmt::format("circling {:.0f} % (left {}, right {})", 100.0 * f.circling_share,
                            minutes(f.circling_left_s), minutes(f.circling_right_s)));
  out.push_back(fmt::format("thermals {}, mean climb {}, best {}", f.thermals.size(), climb(f.mean_thermal_climb_ms),
                            climb(f.best_climb_ms)));
  if (f.best_glide >= 0 && static_cast<std::size_t>(f.best_glide) < f.glides.size()) {
    const fl::Glide& g = f.glides[static_cast<std::size_t>(f.best_glide)];
    out.push_back(fmt::format("best glide L/D {:.1f} over {:.1f} km", g.glide_ratio, g.distance_m / 1000.0));
  } else {
    out.push_back("best glide -");
  }
  for (const fl::WindBand& b : f.wind)
    out.push_back(fmt::format("wind {:.0f}-{:.0f} m: {:.1f} m/s from {:.0f}\u00b0 ({} thermal{})", b.floor_m,
                              b.ceiling_m, b.speed_ms, b.from_deg, b.thermals, b.thermals == 1 ? "" : "s"));
  return out;
}

std::vector<std::string> thermal_row(const fl::Thermal& th) {
  return {utc_clock(th.start.time), climb(th.mean_climb_ms), fmt::format("{:.0f}->{:.0f} m", th.start.alt, th.end.alt),
          fmt::format("{:+.0f} m", th.gain_m), minutes(th.duration_s)};
}

std::optional<std::pair<std::size_t, std::size_t>> points_between(const scene::Track& track, double t0, double t1) {
  const auto& timed = track.timed_points;
  const auto& time = track.time_unix_s;
  if (timed.empty() || !(t0 <= t1)) return std::nullopt;
  if (track.times_rise) {
    const auto lo =
        std::lower_bound(timed.begin(), timed.end(), t0, [&](std::size_t i, double t) { return time[i] < t; });
    const auto hi =
        std::upper_bound(timed.begin(), timed.end(), t1, [&](double t, std::size_t i) { return t < time[i]; });
    if (lo >= hi) return std::nullopt;
    return std::pair{*lo, *std::prev(hi)};
  }
  std::optional<std::pair<std::size_t, std::size_t>> range;
  for (const std::size_t i : timed) {
    const double t = time[i];
    if (t < t0 || t > t1) continue;
    range = range ? std::pair{std::min(range->first, i), std::max(range->second, i)} : std::pair{i, i};
  }
  return range;
}

void flight_statistics(const scene::Track& track, PanelActions& actions) {
  if (!track.flights || track.flights->flights.empty()) return;
  const auto& flights = track.flights->flights;
  for (std::size_t k = 0; k < flights.size(); ++k) {
    const fl::Flight& f = flights[k];
    ImGui::PushID(static_cast<int>(k));
    ImGui::Separator();
    const std::string title =
        flights.size() == 1 ? std::string("Flight") : fmt::format("Flight {} of {}", k + 1, flights.size());
    if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      for (const std::string& line : flight_summary_lines(f)) ImGui::TextUnformatted(line.c_str());
      if (!f.thermals.empty() &&
          ImGui::BeginTable("##thermals", 6, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const char* name : {"#", "start", "climb", "altitude", "gain", "time"}) ImGui::TableSetupColumn(name);
        ImGui::TableHeadersRow();
        // A click flies to the thermal's top, where its marker stands (drawn or not).
        const std::vector<scene::Waypoint> tops = scene::thermal_markers(track);
        for (std::size_t n = 0; n < f.thermals.size(); ++n) {
          const fl::Thermal& th = f.thermals[n];
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::PushID(static_cast<int>(n));
          if (ImGui::Selectable(fmt::format("{}", n + 1).c_str(), false, ImGuiSelectableFlags_SpanAllColumns)) {
            const auto top = std::find_if(tops.begin(), tops.end(),
                                          [&](const scene::Waypoint& w) { return w.time_unix_s == th.end.time; });
            if (top != tops.end()) actions.fly_to_point = *top;
          }
          ImGui::PopID();
          for (const std::string& cell : thermal_row(th)) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(cell.c_str());
          }
        }
        ImGui::EndTable();
      }
    }
    ImGui::PopID();
  }
}

void shade_thermals(ImDrawList* draw, const scene::Track& track, const std::function<float(std::size_t)>& x_px,
                    float top, float bottom) {
  if (!track.flights) return;
  for (const fl::Flight& f : track.flights->flights)
    for (const fl::Thermal& th : f.thermals) {
      const auto span = points_between(track, th.start.time, th.end.time);
      if (!span) continue;
      const float x0 = x_px(span->first), x1 = std::max(x_px(span->second), x0 + 1.0f);
      draw->AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), IM_COL32(255, 140, 30, 55));
    }
}

}  // namespace trailray::ui
