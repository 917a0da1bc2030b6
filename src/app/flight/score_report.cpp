#include "app/flight/score_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ctime>

namespace trailray::app {
namespace {

using track::scoring::DistanceModel;
using track::scoring::Fix;
using track::scoring::ScoreResult;
using track::scoring::TypeResult;

std::string iso_time(double t) {
  const auto secs = static_cast<std::time_t>(std::floor(t));
  std::tm tm{};
  gmtime_r(&secs, &tm);
  return fmt::format("{:04d}-{:02d}-{:02d}T{:02d}:{:02d}:{:02d}Z", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                     tm.tm_hour, tm.tm_min, tm.tm_sec);
}

// Values are rounded already; print them without binary noise.
double tidy(double v) { return std::round(v * 1000.0) / 1000.0; }

nlohmann::json point_json(const TypeResult& t, std::size_t i, const std::vector<Fix>& fixes) {
  nlohmann::json p;
  p["lat"] = t.positions[i].first;
  p["lon"] = t.positions[i].second;
  const int f = t.points[i];
  if (f >= 0) {
    p["time"] = iso_time(fixes[static_cast<std::size_t>(f)].time);
    p["fix"] = f;
  } else {
    p["time"] = nullptr;
    p["fix"] = nullptr;
  }
  return p;
}

nlohmann::json type_json(const ScoreResult& r, const TypeResult& t, const std::vector<Fix>& fixes) {
  nlohmann::json j;
  j["rules"] = r.rules;
  j["type"] = t.type.name;
  j["code"] = t.type.code;
  j["valid"] = t.valid;
  j["exact"] = t.exact;
  j["distance_km"] = tidy(t.distance);
  j["closing_km"] = t.closing < 0 ? nlohmann::json(nullptr) : nlohmann::json(tidy(t.closing));
  j["penalty_km"] = tidy(t.penalty);
  j["multiplier"] = t.type.multiplier;
  j["score"] = tidy(t.score);
  j["legs_km"] = nlohmann::json::array();
  for (double l : t.legs) j["legs_km"].push_back(tidy(l));
  j["turnpoints"] = nlohmann::json::array();
  for (std::size_t i = 0; i < t.points.size(); ++i) j["turnpoints"].push_back(point_json(t, i, fixes));
  if (t.closing_in >= 0) j["closing_fixes"] = {t.closing_in, t.closing_out};
  return j;
}

}  // namespace

nlohmann::json score_json(const ScoreResult& r, const std::vector<Fix>& fixes) {
  nlohmann::json doc;
  if (r.best >= 0) {
    doc = type_json(r, r.by_type[static_cast<std::size_t>(r.best)], fixes);
  } else {
    doc["rules"] = r.rules;
    doc["type"] = nullptr;
    doc["code"] = nullptr;
    doc["score"] = 0;
  }
  doc["distance_model"] = r.model == DistanceModel::Fcc ? "fcc" : "geodesic";
  doc["launch"] = {{"fix", r.flight.launch}, {"time", iso_time(fixes[static_cast<std::size_t>(r.flight.launch)].time)}};
  doc["landing"] = {{"fix", r.flight.landing},
                    {"time", iso_time(fixes[static_cast<std::size_t>(r.flight.landing)].time)}};
  doc["by_type"] = nlohmann::json::array();
  for (const TypeResult& t : r.by_type) doc["by_type"].push_back(type_json(r, t, fixes));
  return doc;
}

std::string score_table(const ScoreResult& r, const std::vector<Fix>& fixes) {
  std::string s;
  s += fmt::format("rules {} ({} distances), flight {} to {} (fixes {}..{})\n", r.rules,
                   r.model == DistanceModel::Fcc ? "FCC" : "geodesic",
                   iso_time(fixes[static_cast<std::size_t>(r.flight.launch)].time),
                   iso_time(fixes[static_cast<std::size_t>(r.flight.landing)].time), r.flight.launch, r.flight.landing);
  s += fmt::format("  {:<38} {:>4} {:>10} {:>9} {:>9} {:>5} {:>9}\n", "type", "code", "distance", "closing", "penalty",
                   "mult", "score");
  for (std::size_t i = 0; i < r.by_type.size(); ++i) {
    const TypeResult& t = r.by_type[i];
    const std::string mark = static_cast<int>(i) == r.best ? "*" : " ";
    if (!t.valid) {
      s += fmt::format("{} {:<38} {:>4} {:>10}{}\n", mark, t.type.name, t.type.code, "-",
                       t.exact ? "" : "   (not better than the best)");
      continue;
    }
    s += fmt::format("{} {:<38} {:>4} {:>7.2f} km {:>9} {:>6.2f} km {:>5.2f} {:>9.2f}{}\n", mark, t.type.name,
                     t.type.code, t.distance, t.closing < 0 ? std::string("-") : fmt::format("{:.2f} km", t.closing),
                     t.penalty, t.type.multiplier, t.score,
                     t.exact ? "" : "   (at least; search stopped below the best)");
  }
  if (r.best < 0) {
    s += "no route scores under these rules\n";
    return s;
  }
  const TypeResult& b = r.by_type[static_cast<std::size_t>(r.best)];
  s += fmt::format("best: {} {:.2f} points\n", b.type.name, b.score);
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const int f = b.points[i];
    s += fmt::format("  {:<7} {:>10.5f} {:>11.5f}  {}  fix {}",
                     b.type.code == "od" && i == 0 ? "start"
                     : b.type.code == "od" && i + 1 == b.points.size()
                         ? "finish"
                         : fmt::format("TP{}", b.type.code == "od" ? i : i + 1),
                     b.positions[i].first, b.positions[i].second,
                     f >= 0 ? iso_time(fixes[static_cast<std::size_t>(f)].time) : std::string("(moved)             "),
                     f >= 0 ? std::to_string(f) : std::string("-"));
    s += i < b.legs.size() ? fmt::format("   leg {:.2f} km\n", b.legs[i]) : "\n";
  }
  return s;
}

}  // namespace trailray::app
