#include "app/pictures/bench_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/common/terminal_diagnostics.hpp"
#include "app/options/camera_options.hpp"
#include "app/pictures/bench_datasets.hpp"
#include "app/pictures/bench_runner.hpp"

namespace trailray::app {
namespace {

constexpr int kMaxFrames = 1000;
// Ratios the issue sets for the capsules at the largest walk (1M points in the default run).
constexpr double kTargetCapsuleOverRibbon = 1.5, kTargetCapsuleOverTube = 0.7, kTargetMemoryRatio = 1.0 / 8.0;

struct BenchArgs {
  std::string points = "10000,100000,1000000";
  std::string size = "1920x1080";
  int frames = 20;
  std::string data = "../shared/data";
  bool json = false;
  std::string overlay = "split";
  std::string many;  // TRACKSxPOINTS, empty: no many-track scenario
  std::string lod = "on";
};

// `--many 10000x1000`: the many-track scenario's size (tracks x points per track).
std::optional<std::pair<std::size_t, std::size_t>> parse_many(const std::string& text) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  std::size_t tracks = 0, points = 0;
  const char* begin = text.data();
  const auto [t_end, t_ec] = std::from_chars(begin, begin + x, tracks);
  const auto [p_end, p_ec] = std::from_chars(begin + x + 1, begin + text.size(), points);
  if (t_ec != std::errc() || t_end != begin + x || p_ec != std::errc() || p_end != begin + text.size())
    return std::nullopt;
  if (tracks < 1 || points < 2 || tracks > kMaxBenchPoints || points > kMaxBenchPoints ||
      tracks * points > 10 * kMaxBenchPoints)
    return std::nullopt;
  return std::pair{tracks, points};
}

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

double ratio(double a, double b) { return b > 0.0 ? a / b : 0.0; }
double per_point(std::size_t bytes, std::size_t points) {
  return points > 0 ? static_cast<double>(bytes) / static_cast<double>(points) : 0.0;
}

nlohmann::json row_json(const BenchRow& r) {
  return {{"name", r.name},
          {"kind", r.kind},
          {"points", r.points},
          {"segments", r.segments},
          {"capsule_ms", r.capsule_ms},
          {"capsule_overlay_ms", r.capsule_overlay_ms},
          {"capsule_total_ms", r.capsule_total_ms},
          {"capsules_drawn", r.capsules_drawn},
          {"capsule_upload_ms", r.capsule_upload_ms},
          {"capsule_per_track_total_ms", r.capsule_per_track_total_ms},
          {"ribbon_ms", r.ribbon_ms},
          {"tube_ms", r.tube_ms},
          // The capsules' cost is both passes: a frame with tracks always draws the overlay too.
          {"capsule_over_ribbon", ratio(r.capsule_total_ms, r.ribbon_ms)},
          {"capsule_over_tube", ratio(r.capsule_total_ms, r.tube_ms)},
          {"capsule_visible_over_ribbon", ratio(r.capsule_ms, r.ribbon_ms)},
          {"capsule_visible_over_tube", ratio(r.capsule_ms, r.tube_ms)},
          {"capsule_bytes_per_point", per_point(r.capsule_bytes, r.points)},
          {"ribbon_bytes_per_point", per_point(r.ribbon_bytes, r.points)},
          {"tube_bytes_per_point", per_point(r.tube_bytes, r.points)},
          {"capsule_over_tube_bytes", ratio(static_cast<double>(r.capsule_bytes), static_cast<double>(r.tube_bytes))},
          {"tube_radius_m", r.tube_radius_m},
          {"view_distance_m", r.view_distance_m},
          {"timing", r.gpu_timed ? "gpu" : "cpu"}};
}

std::string table(const std::vector<BenchRow>& rows) {
  // cap/rib and cap/tube compare the capsules' total (visible + overlay) with each reference.
  std::string out = fmt::format("{:<44} {:>8} {:>9} {:>10} {:>10} {:>10} {:>10} {:>10} {:>8} {:>8} {:>8} {:>8} {:>8}\n",
                                "dataset", "points", "capsules", "capsule", "overlay", "cap total", "ribbon", "tube",
                                "cap/rib", "cap/tube", "cap B/pt", "tube B/pt", "mem c/t");
  out += fmt::format("{:<44} {:>8} {:>9} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "", "", "drawn", "ms", "ms", "ms", "ms",
                     "ms");
  for (const BenchRow& r : rows)
    out += fmt::format(
        "{:<44} {:>8} {:>9} {:>10.3f} {:>10.3f} {:>10.3f} {:>10.3f} {:>10.3f} {:>8.2f} {:>8.2f} {:>8.1f} {:>8.1f} "
        "{:>8.3f}\n",
        r.name.size() > 44 ? r.name.substr(0, 41) + "..." : r.name, r.points, r.capsules_drawn, r.capsule_ms,
        r.capsule_overlay_ms, r.capsule_total_ms, r.ribbon_ms, r.tube_ms, ratio(r.capsule_total_ms, r.ribbon_ms),
        ratio(r.capsule_total_ms, r.tube_ms), per_point(r.capsule_bytes, r.points), per_point(r.tube_bytes, r.points),
        ratio(static_cast<double>(r.capsule_bytes), static_cast<double>(r.tube_bytes)));
  for (const BenchRow& r : rows)
    if (r.capsule_per_track_total_ms > 0.0)
      out += fmt::format("{}: capsules of all tracks in one buffer {:.3f} ms, a buffer per track {:.3f} ms ({:.2f}x)\n",
                         r.name, r.capsule_total_ms, r.capsule_per_track_total_ms,
                         ratio(r.capsule_per_track_total_ms, r.capsule_total_ms));
  return out;
}

// The targets, checked on the largest random walk.
nlohmann::json targets_json(const BenchRow& r) {
  const double over_ribbon = ratio(r.capsule_total_ms, r.ribbon_ms), over_tube = ratio(r.capsule_total_ms, r.tube_ms);
  const double memory = ratio(static_cast<double>(r.capsule_bytes), static_cast<double>(r.tube_bytes));
  return {{"dataset", r.name},
          {"capsule_over_ribbon",
           {{"value", over_ribbon},
            {"target", kTargetCapsuleOverRibbon},
            {"met", over_ribbon <= kTargetCapsuleOverRibbon}}},
          {"capsule_over_tube",
           {{"value", over_tube}, {"target", kTargetCapsuleOverTube}, {"met", over_tube <= kTargetCapsuleOverTube}}},
          {"capsule_over_tube_bytes",
           {{"value", memory}, {"target", kTargetMemoryRatio}, {"met", memory <= kTargetMemoryRatio}}}};
}

std::string targets_text(const nlohmann::json& t) {
  std::string out = fmt::format("targets at {}:", t["dataset"].get<std::string>());
  for (const char* key : {"capsule_over_ribbon", "capsule_over_tube", "capsule_over_tube_bytes"})
    out += fmt::format(" {} {:.3f} (<= {:.3f}: {})", key, t[key]["value"].get<double>(), t[key]["target"].get<double>(),
                       t[key]["met"].get<bool>() ? "met" : "missed");
  return out + "\n";
}

int run_bench_tracks(const BenchArgs& a) {
  const auto counts = parse_point_counts(a.points);
  if (!counts.ok()) throw CLI::ValidationError("--points", counts.error);
  const scene::Lens lens = parse_lens(a.size, scene::kDefaultVerticalFovDeg);
  if (a.frames < 1 || a.frames > kMaxFrames)
    throw CLI::ValidationError("--frames", fmt::format("'{}' is not a frame count in 1..{}", a.frames, kMaxFrames));

  std::optional<std::pair<std::size_t, std::size_t>> many;
  if (!a.many.empty()) {
    many = parse_many(a.many);
    if (!many)
      throw CLI::ValidationError("--many", fmt::format("'{}' is not TRACKSxPOINTS (e.g. 10000x1000, at most {} points "
                                                       "a track and {} in all)",
                                                       a.many, kMaxBenchPoints, 10 * kMaxBenchPoints));
  }
  TerminalDiagnostics diagnostics;
  RealTracks real;
  if (a.data != "none") real = load_real_tracks(a.data);
  for (const std::string& note : real.skipped) diagnostics.info("skipped " + note);

  BenchSettings settings;
  settings.lens = lens;
  settings.frames = a.frames;
  settings.split_overlay = a.overlay == "split";
  settings.level_of_detail = a.lod == "on";
  TrackBench bench(settings);
  const std::string timing =
      bench.gpu_timing() ? "gpu (EXT_disjoint_timer_query)" : "cpu (wall time around the draw and glFinish)";
  diagnostics.info(fmt::format("{} at {}x{}, {} timed frames after {} warm-up, track width {} px, timing: {}",
                               bench.renderer(), lens.width_px, lens.height_px, a.frames, settings.warmup_frames,
                               settings.width_px, timing));

  const std::size_t total = counts.value->size() + (many ? 1 : 0) + real.datasets.size();
  std::vector<BenchRow> rows;
  std::optional<BenchRow> largest_walk;
  std::size_t index = 0;
  const auto measure = [&](const BenchDataset& d) {
    const auto start = std::chrono::steady_clock::now();
    const std::string what = fmt::format("[{}/{}] {} ({} points):", ++index, total, d.name, d.point_count());
    std::string done;
    BenchRow row = bench.run(d, [&](const std::string& technique) {
      done += " " + technique;
      diagnostics.progress(what + done);
    });
    diagnostics.progress_done();
    diagnostics.info(fmt::format("{}{} ({:.1f} s)", what, done,
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
    if (d.kind == "random_walk" && (!largest_walk || row.points >= largest_walk->points)) largest_walk = row;
    rows.push_back(std::move(row));
  };
  for (std::size_t points : *counts.value) measure(make_random_walk(points));
  if (many) measure(make_many_walks(many->first, many->second));
  // A real track that cannot be framed or uploaded is reported and left out; the walks must run.
  for (const BenchDataset& d : real.datasets) try {
      measure(d);
    } catch (const std::exception& e) {
      diagnostics.progress_done();
      diagnostics.info(fmt::format("{} failed", d.name));
      real.skipped.push_back(d.name + ": " + e.what());
    }

  std::optional<nlohmann::json> targets;
  if (largest_walk) targets = targets_json(*largest_walk);
  if (a.json) {
    nlohmann::json doc{{"renderer", bench.renderer()},
                       {"timing", bench.gpu_timing() ? "gpu" : "cpu"},
                       {"size", {{"width", lens.width_px}, {"height", lens.height_px}}},
                       {"frames", a.frames},
                       {"warmup_frames", settings.warmup_frames},
                       {"width_px", settings.width_px},
                       {"overlay", a.overlay},
                       {"lod", a.lod},
                       {"datasets", nlohmann::json::array()},
                       {"skipped", real.skipped}};
    for (const BenchRow& r : rows) doc["datasets"].push_back(row_json(r));
    if (targets) doc["targets"] = *targets;
    std::cout << doc.dump(2) << '\n';
  } else {
    fmt::print("renderer: {}; {}x{}; median of {} frames; track width {} px; overlay: {}; LOD: {}; timing: {}\n",
               bench.renderer(), lens.width_px, lens.height_px, a.frames, settings.width_px, a.overlay, a.lod, timing);
    fmt::print("{}", table(rows));
    if (targets) fmt::print("{}", targets_text(*targets));
  }
  return 0;
}

}  // namespace

scene::Result<std::vector<std::size_t>> parse_point_counts(std::string_view text) {
  scene::Result<std::vector<std::size_t>> r;
  const std::string form =
      fmt::format("point counts in 2..{}, separated by commas, e.g. 10000,100000", kMaxBenchPoints);
  std::vector<std::size_t> counts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        trim(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    std::size_t value = 0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || value < 2 || value > kMaxBenchPoints) {
      const std::string where = item == text ? std::string() : fmt::format(" (in '{}')", text);
      r.error = fmt::format("'{}'{} is not a point count: expected {}", item, where, form);
      return r;
    }
    counts.push_back(value);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  r.value = std::move(counts);
  return r;
}

void add_bench_command(CLI::App& app, int& exit_code) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that print figures (they never fail on them)");
  bench->require_subcommand(1);
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "tracks", "Track pass time and GPU memory: capsules against a screen-space ribbon and an 8-sided tube mesh");
  cmd->footer(
      "Draws seeded random walks of each --points size, then every .gpx and .igc file under --data/gpx and\n"
      "--data/igc, framed over a flat ground, with each technique at the same width (5 px). Times are medians\n"
      "over --frames frames after 2 warm-up frames: GPU time where the context has EXT_disjoint_timer_query,\n"
      "else wall time around the draw and a glFinish. Progress goes to standard error.\n"
      "Exit status: 0 measured, 1 GL failed, 2 a usage error.");
  cmd->add_option("--points", args->points, "Random walk sizes (default 10000,100000,1000000)")->type_name("LIST");
  cmd->add_option("--size", args->size, "Picture size in pixels (default 1920x1080)")->type_name("WxH");
  cmd->add_option("--frames", args->frames, "Timed frames per technique and dataset (default 20)")->type_name("N");
  cmd->add_option("--data", args->data,
                  "Folder with gpx/ and igc/ subfolders of real tracks, or none (default ../shared/data)")
      ->type_name("DIR");
  cmd->add_flag("--json", args->json, "Print one JSON document instead of the table");
  cmd->add_option("--overlay", args->overlay,
                  "split: the overlay traces only capsules the terrain may hide, as the renderer draws it (default);\n"
                  "full: every capsule, to compare")
      ->check(CLI::IsMember({"split", "full"}))
      ->type_name("MODE");
  cmd->add_option("--many", args->many,
                  "Also draw TRACKS random walks of POINTS points each, spread over 30 km x 30 km, each in its own\n"
                  "colour, all in one buffer as the renderer draws a scene's tracks, and again with a buffer per\n"
                  "track to compare (e.g. 10000x1000: a season of tracks; the tube is left out above 2M points)")
      ->type_name("TRACKSxPOINTS");
  cmd->add_option("--lod", args->lod,
                  "on: the capsules' level of detail merges capsules shorter than a pixel, as the renderer draws\n"
                  "them (default); off: every capsule, to compare")
      ->check(CLI::IsMember({"on", "off"}))
      ->type_name("on|off");
  cmd->callback([args, &exit_code] { exit_code = run_bench_tracks(*args); });
}

}  // namespace trailray::app
