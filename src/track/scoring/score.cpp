#include "track/scoring/score.hpp"

#include <algorithm>

#include "track/scoring/cylinders.hpp"

namespace trailray::track::scoring {
namespace {

ScoreResult score_window(const std::vector<Fix>& fixes, const RuleSet& rules, const ScoreOptions& options,
                         const FlightWindow& w) {
  ScoreResult r;
  r.rules = rules.name;
  r.model = options.model;
  r.flight = w;
  const Metric metric(fixes, options.model);
  const RangeTree tree(metric, w.launch, w.landing);
  ClosingFinder closing(metric, tree);
  r.by_type.resize(rules.types.size());
  // The closed types first, highest multiplier first, each above the best score found so far
  // (starting from a free-distance route known from the cheap first passes): a type with a lower
  // multiplier often cannot reach it at all. The free distance last: its costly passes then only
  // look at routes that beat the best closed one.
  const FreeDistanceStart start = prepare_free_distance(metric, tree);
  std::vector<std::size_t> order;
  double floor = -1.0;
  for (std::size_t i = 0; i < rules.types.size(); ++i)
    if (rules.types[i].shape != Shape::FreeDistance)
      order.push_back(i);
    else if (rules.types[i].cylinders <= 0)
      floor = std::max(floor, known_route_score(start, rules.types[i]));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return rules.types[x].multiplier > rules.types[y].multiplier; });
  for (std::size_t i = 0; i < rules.types.size(); ++i)
    if (rules.types[i].shape == Shape::FreeDistance) order.push_back(i);
  if (options.all_types) floor = -1.0;
  double closed_best = -1.0;
  for (std::size_t i : order) {
    const FlightType& t = rules.types[i];
    TypeResult tr;
    switch (t.shape) {
      case Shape::FreeDistance:
        tr = optimise_free_distance(metric, tree, t, start, options.all_types ? -1.0 : closed_best);
        break;
      case Shape::Triangle:
      case Shape::OutAndReturn2:
        tr = optimise_closed(metric, tree, closing, t, floor);
        break;
      case Shape::OutAndReturn1:
        tr = optimise_out_and_return1(metric, tree, t, floor);
        break;
    }
    if (tr.positions.empty())
      for (int f : tr.points)
        tr.positions.emplace_back(fixes[static_cast<std::size_t>(f)].lat, fixes[static_cast<std::size_t>(f)].lon);
    if (t.cylinders > 0) apply_fai_cylinders(metric, tr);
    // Cylinders shrink the legs after the optimisation, so the floor only rises without them.
    if (tr.valid && t.cylinders <= 0 && !options.all_types) {
      floor = std::max(floor, tr.score);
      if (t.shape != Shape::FreeDistance) closed_best = std::max(closed_best, tr.score);
    }
    r.by_type[i] = std::move(tr);
  }
  for (std::size_t i = 0; i < r.by_type.size(); ++i) {
    const TypeResult& tr = r.by_type[i];
    if (!tr.valid) continue;
    if (r.best < 0 || tr.score > r.by_type[static_cast<std::size_t>(r.best)].score) r.best = static_cast<int>(i);
  }
  return r;
}

double best_score(const ScoreResult& r) {
  return r.best < 0 ? -1.0 : r.by_type[static_cast<std::size_t>(r.best)].score;
}

}  // namespace

ScoreResult score_flight(const std::vector<Fix>& fixes, const RuleSet& rules, const ScoreOptions& options) {
  if (fixes.size() < 5) {
    ScoreResult r;
    r.rules = rules.name;
    r.model = options.model;
    return r;
  }
  std::vector<FlightWindow> windows;
  if (options.trim)
    windows = detect_flights(fixes);
  else
    windows.push_back({0, static_cast<int>(fixes.size()) - 1});
  // Several flights in one log: the best-scoring one counts, as with the reference scorer.
  ScoreResult best;
  bool have = false;
  for (const FlightWindow& w : windows) {
    ScoreResult r = score_window(fixes, rules, options, w);
    if (!have || best_score(r) > best_score(best)) {
      best = std::move(r);
      have = true;
    }
  }
  return best;
}

}  // namespace trailray::track::scoring
