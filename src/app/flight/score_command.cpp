#include "app/flight/score_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <memory>

#include "app/common/terminal_diagnostics.hpp"
#include "app/flight/score_report.hpp"
#include "track/scoring/score.hpp"

namespace trailray::app {
namespace {

struct ScoreArgs {
  std::string file;
  std::string rules = "xcontest";
  std::string distance = "fcc";
  bool json = false;
  bool no_trim = false;
  bool all_types = false;
};

int run_score(const ScoreArgs& a) {
  namespace sc = track::scoring;
  TerminalDiagnostics diagnostics;
  const auto rules = sc::rule_set(a.rules);
  if (!rules) {
    diagnostics.error(
        fmt::format("unknown rule set '{}' (one of: {})", a.rules, fmt::join(sc::rule_set_names(), ", ")));
    return 2;
  }
  const sc::FixList list = sc::read_any_scoring_fixes(a.file);  // IGC, or a GPX/FIT/... flight's track
  if (list.error) {
    diagnostics.error(*list.error);
    return 1;
  }
  if (list.fixes.size() < 5) {
    diagnostics.error(fmt::format("{}: {} valid fixes (of {} B records); scoring needs at least 5", a.file,
                                  list.fixes.size(), list.b_records));
    return 1;
  }
  sc::ScoreOptions options;
  options.model = a.distance == "geodesic" ? sc::DistanceModel::Geodesic : sc::DistanceModel::Fcc;
  options.trim = !a.no_trim;
  options.all_types = a.all_types;
  const auto t0 = std::chrono::steady_clock::now();
  const sc::ScoreResult r = sc::score_flight(list.fixes, *rules, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    nlohmann::json doc = score_json(r, list.fixes);
    doc["solve_seconds"] = seconds;  // launch detection and optimisation, not reading the file
    std::cout << doc.dump(2) << '\n';
  } else
    fmt::print("{}", score_table(r, list.fixes));
  return 0;
}

}  // namespace

void add_score_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ScoreArgs>();
  CLI::App* cmd =
      app.add_subcommand("score", "Cross-country score of an IGC flight (free distance, triangles, out-and-return)");
  cmd->footer(
      "Every flight type of the rule set is optimised exactly (branch and bound over the fixes of\n"
      "the log: turnpoints are fixes) and the best-scoring type is reported; --json adds the best\n"
      "of each type under by_type (\"exact\": false where a type's search stopped because it could\n"
      "not beat the best; --all-types finds every type's own optimum).\n"
      "Launch and landing are detected from 10 s averages of ground and vertical speed (--no-trim\n"
      "scores the whole log). Legs and closing are rounded to 0.01 km before summing; fai,\n"
      "fai-oar, fai-cylinders and xcleague round the distance and the score to 0.1.\n"
      "Distances: --distance fcc (default) is the FCC ellipsoidal formula, which the reference\n"
      "scorer igc-xc-score uses by default, so scores agree with it to the last digit; geodesic is\n"
      "the exact WGS84 geodesic (Karney; the same as Vincenty to < 1 mm, igc-xc-score's hp mode).\n"
      "The two differ by about 5 m per 100 km: a few hundredths of a point.\n"
      "Rule sets: xcontest, ffvl, fai, fai-oar, fai-cylinders, xcleague.\n"
      "Exit status: 0 scored, 1 when the file cannot be read or has too few fixes, 2 for a usage error.");
  cmd->add_option("TRACK", args->file, "IGC flight log")->required()->type_name("FILE");
  cmd->add_option("--rules", args->rules, "Rule set: xcontest, ffvl, fai, fai-oar, fai-cylinders, xcleague")
      ->default_str("xcontest")
      ->type_name("NAME");
  cmd->add_option("--distance", args->distance, "Distance model: fcc or geodesic")
      ->check(CLI::IsMember({"fcc", "geodesic"}))
      ->default_str("fcc")
      ->type_name("MODEL");
  cmd->add_flag("--no-trim", args->no_trim, "Score the whole log, not only the detected flight");
  cmd->add_flag("--all-types", args->all_types,
                "Optimise every type to its own optimum (by default a type stops once it cannot beat the best)");
  cmd->add_flag("--json", args->json, "Print one JSON document instead of a table");
  cmd->callback([args, &exit_code] { exit_code = run_score(*args); });
}

}  // namespace trailray::app
