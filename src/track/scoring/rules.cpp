#include "track/scoring/rules.hpp"

namespace trailray::track::scoring {
namespace {

FlightType od(std::string name, bool r01 = false, double min_distance = 0.0) {
  FlightType t;
  t.name = std::move(name);
  t.code = "od";
  t.shape = Shape::FreeDistance;
  t.final_rounding_01 = r01;
  t.min_distance = min_distance;
  return t;
}

FlightType tri(std::string name, bool fai, double mult, double fixed, double rel, double free_km, bool r01) {
  FlightType t;
  t.name = std::move(name);
  t.code = fai ? "fai" : "tri";
  t.shape = Shape::Triangle;
  t.multiplier = mult;
  t.min_side = fai ? 0.28 : 0.0;
  t.closing_fixed = fixed;
  t.closing_relative = rel;
  t.closing_free = free_km;
  t.final_rounding_01 = r01;
  return t;
}

FlightType with_cylinders(FlightType t) {
  t.cylinders = 0.4;
  return t;
}

}  // namespace

std::vector<std::string> rule_set_names() {
  return {"xcontest", "ffvl", "fai", "fai-oar", "fai-cylinders", "xcleague"};
}

std::optional<RuleSet> rule_set(const std::string& name) {
  RuleSet r;
  r.name = name;
  if (name == "xcontest") {
    // No free closing: any closing distance is the penalty (closing_free < 0 for the open
    // triangles, 0 for the closed ones: the same thing).
    r.types = {od("Free Flight"), tri("Free Triangle", false, 1.2, 0, 0.2, -1, false),
               tri("FAI Triangle", true, 1.4, 0, 0.2, -1, false),
               tri("Closed Free Triangle", false, 1.4, 0, 0.05, 0, false),
               tri("Closed FAI Triangle", true, 1.6, 0, 0.05, 0, false)};
  } else if (name == "ffvl") {
    r.types = {od("Distance 3 points"), tri("Triangle plat", false, 1.2, 3, 0.05, 3, false),
               tri("Triangle FAI", true, 1.4, 3, 0.05, 3, false)};
  } else if (name == "fai" || name == "fai-cylinders") {
    r.types = {od("Free Distance around 3 TPs", true), tri("Free Triangle", false, 1.2, 0.8, 0, 0.8, true),
               tri("FAI Triangle", true, 1.4, 0.8, 0, 0.8, true)};
    if (name == "fai-cylinders")
      for (auto& t : r.types) t = with_cylinders(t);
  } else if (name == "fai-oar") {
    FlightType t;
    t.name = "Out-and-Return Distance";
    t.code = "oar";
    t.shape = Shape::OutAndReturn1;
    t.closing_fixed = 0.8;
    t.closing_free = 0.8;
    t.final_rounding_01 = true;
    r.types = {t};
  } else if (name == "xcleague") {
    auto oar = [](std::string n, double mult, double min_d) {
      FlightType t;
      t.name = std::move(n);
      t.code = "oar";
      t.shape = Shape::OutAndReturn2;
      t.multiplier = mult;
      t.min_distance = min_d;
      t.closing_fixed = 0.8;
      t.final_rounding_01 = true;
      return t;
    };
    auto xtri = [](std::string n, bool fai, double mult, double min_d) {
      FlightType t = tri(std::move(n), fai, mult, 0.8, 0, -1, true);
      t.code = "tri";  // the reference scorer codes XCLeague's FAI triangles "tri" as well
      t.min_distance = min_d;
      if (!fai) {
        t.min_side = 0.15;
        t.max_side = 0.45;
      }
      return t;
    };
    r.types = {oar("Out-and-Return Distance >=35km", 2.0, 35),       oar("Out-and-Return Distance >=15km", 1.5, 15),
               oar("Out-and-Return Distance >=5km (Clubs)", 1.2, 5), od("Turnpoint Flight", true, 5),
               xtri("Flat Triangle >=35km", false, 2.0, 35),         xtri("Flat Triangle >=15km", false, 1.5, 15),
               xtri("Flat Triangle >=5km (Clubs)", false, 1.2, 5),   xtri("FAI Triangle >=25km", true, 2.3, 25),
               xtri("FAI Triangle >=15km", true, 2.0, 15),           xtri("FAI Triangle >=5km (Clubs)", true, 1.5, 5)};
  } else {
    return std::nullopt;
  }
  return r;
}

}  // namespace trailray::track::scoring
