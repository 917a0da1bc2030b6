// `trailray render TRACK...` as a user runs it, on small pictures: every wrong track style value
// is a usage error naming its option; a red track lands where its points project and widens
// with --width; colour by speed shows the colormap's two ends on a track whose speed doubles; the
// legend takes the bottom-left panel and nothing else; several tracks get palette colours and a
// key; occlusion, curtains over the shared DEMs; odd tracks (one point, a repeated point, an
// empty segment, a gap) render without bridging anything.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "app/options/style_options.hpp"
#include "app/track_cli_support.hpp"
#include "scene/camera/camera.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene/text/legend.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/text/text_raster.hpp"
#include "scene/tracks/track_building.hpp"
#include "track/io/load.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
constexpr std::uint32_t kWidth = 320, kHeight = 180;
// Small, sharp pictures: no SSAO or haze to tint the track, a fixed sun.
const std::string kPicture = " --terrain none --no-ssao --no-atmosphere --size 320x180 --time 2024-06-18T10:00:00Z";

using Rgb = Picture::Rgb;

// A track drawn '#ff0000': lit or in shade it keeps far more red than green or blue, which
// neither the grey neutral ground nor the blue sky has.
bool red(const Rgb& p) { return p.r >= 90 && p.r > 2 * p.g + 40 && p.r > 2 * p.b + 40; }

// Red mixed with the ground under it: a translucent ghost of a red track over green terrain.
bool reddish(const Rgb& p) { return p.r > p.g + 30 && p.r > p.b + 30; }

std::size_t count(const Picture& picture, bool (*what)(const Rgb&)) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) n += what(picture.at(x, y)) ? 1 : 0;
  return n;
}

// Whether any pixel within `radius` of (x, y) is `what`.
bool any_near(const Picture& picture, double x, double y, int radius, bool (*what)(const Rgb&)) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double px = std::round(x) + dx, py = std::round(y) + dy;
      if (picture.inside(px, py) && what(picture.at(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py))))
        return true;
    }
  return false;
}

std::optional<terrain::ScreenPoint> project(const scene::Camera& camera, const GpxPoint& p) {
  return camera.project(scene::ecef_from({p.lat, p.lon, p.ele}));
}

// Runs `trailray render` and reads the picture back (a failed run fails the test).
Picture render_to(const RenderEnv& env, const std::string& args, const std::string& name) {
  const std::string out = env.file(name);
  const auto r = run_command(env.prefix() + args + " -o " + shell_quote(out) + " 2>&1");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  if (r.status != 0) return {};
  return read_picture(out);
}

// Keeps a copy of a picture for a person to look at, as track_cli_NAME in $TRAILRAY_TEST_IMAGE_DIR
// when that is set (the render tests' convention).
void keep(const RenderEnv& env, const std::string& name) {
  const char* folder = std::getenv("TRAILRAY_TEST_IMAGE_DIR");
  if (folder == nullptr || *folder == '\0') return;
  std::error_code ec;
  std::filesystem::copy_file(env.file(name), std::filesystem::path(folder) / ("track_cli_" + name),
                             std::filesystem::copy_options::overwrite_existing, ec);
}

// A straight hike east, 1.5 km: 61 points 25 m apart, 10 s apart, at 1000 m.
std::vector<GpxPoint> straight_hike() { return east_line(kLat, kLon, 0.0, 61, 25.0, kT0, 10.0, 1000.0); }

// 40 points 28 m apart, then 40 points 56 m apart, every 10 s: 10.08 then 20.16 km/h.
std::vector<GpxPoint> doubling_speed_hike() {
  auto points = east_line(kLat, kLon, 0.0, 40, 28.0, kT0, 10.0, 1000.0);
  const auto fast = east_line(kLat, kLon, 40 * 28.0, 40, 56.0, kT0 + 400.0, 10.0, 1000.0);
  points.insert(points.end(), fast.begin(), fast.end());
  return points;
}

// ---------------------------------------------------------------------------------------------
// Options

TEST(TrackRenderCli, WrongTrackStyleValuesAreUsageErrorsNamingTheOption) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  // The track first: --color takes every following word up to the next option.
  const std::string common = shell_quote(gpx) + kPicture + " -o " + shell_quote(env.file("out.png"));
  struct Case {
    std::string args, option;
  };
  const Case cases[] = {
      {"--width 8", "--width"},
      {"--width 0px", "--width"},
      {"--width -3m", "--width"},
      {"--width 8km", "--width"},
      {"--color-by sped", "--color-by"},
      {"--color-by speed --colormap jet", "--colormap"},
      {"--color-by speed --range 5:5", "--range"},
      {"--color-by speed --range a:b", "--range"},
      {"--color red", "--color"},
      {"--occluded-alpha 1.5", "--occluded-alpha"},
      {"--occlusion-fade 500:100", "--occlusion-fade"},
      {"--occlusion maybe", "--occlusion"},
      {"--legend maybe", "--legend"},
  };
  for (const Case& c : cases) {
    const auto r = run_command(env.prefix() + common + " " + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.option), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(env.file("out.png")));
}

TEST(TrackRenderCli, TwoColoursForThreeTracksIsRefused) {
  RenderEnv env;
  const std::string gpx =
      env.write_gpx("three.gpx", {{"A", {east_line(kLat, kLon, 0.0, 20, 25.0, kT0, 10.0, 1000.0, 0.0)}},
                                  {"B", {east_line(kLat, kLon, 0.0, 20, 25.0, kT0, 10.0, 1000.0, 300.0)}},
                                  {"C", {east_line(kLat, kLon, 0.0, 20, 25.0, kT0, 10.0, 1000.0, 600.0)}}});
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPicture + " --color '#ff0000' --color '#00ff00' -o " +
                             shell_quote(env.file("out.png")) + " 2>&1");
  EXPECT_TRUE(r.status == 1 || r.status == 2) << r.out;
  EXPECT_NE(r.out.find("--color"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("once per track"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(env.file("out.png")));
}

TEST(TrackRenderCli, HeightAboveGroundWithoutTerrainSaysToGiveTerrain) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPicture + " --color-by agl -o " +
                             shell_quote(env.file("out.png")) + " 2>&1");
  EXPECT_TRUE(r.status == 1 || r.status == 2) << r.out;
  EXPECT_NE(r.out.find("agl"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--terrain"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(env.file("out.png")));
}

// ---------------------------------------------------------------------------------------------
// Solid colour and width

TEST(TrackRenderCli, ARedTrackIsDrawnWhereItsPointsProject) {
  RenderEnv env;
  const auto points = straight_hike();
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {points}}});
  const Picture drawn = render_to(env, shell_quote(gpx) + kPicture + " --color '#ff0000'", "red.png");
  ASSERT_EQ(drawn.width, kWidth);
  ASSERT_EQ(drawn.height, kHeight);
  keep(env, "red.png");
  const scene::Camera camera = framing_camera(points, kWidth, kHeight);
  std::size_t projected = 0;
  for (std::size_t i = 2; i + 2 < points.size(); ++i) {  // the ends are pulled in by smoothing
    const auto at = project(camera, points[i]);
    ASSERT_TRUE(at.has_value());
    if (!drawn.inside(at->x_px, at->y_px)) continue;
    ++projected;
    EXPECT_TRUE(any_near(drawn, at->x_px, at->y_px, 3, red)) << "point " << i << " at " << at->x_px << "," << at->y_px;
  }
  EXPECT_GT(projected, 50u) << "the framing shows the track";
  EXPECT_GT(count(drawn, red), 300u);

  // The same track in green: no red anywhere, so the red above is the track's.
  const Picture green = render_to(env, shell_quote(gpx) + kPicture + " --color '#00ff00'", "green.png");
  EXPECT_EQ(count(green, red), 0u);
}

TEST(TrackRenderCli, WiderTracksCoverMorePixels) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string common = shell_quote(gpx) + kPicture + " --color '#ff0000' --width ";
  const std::size_t thin = count(render_to(env, common + "2px", "thin.png"), red);
  const std::size_t thick = count(render_to(env, common + "12px", "thick.png"), red);
  keep(env, "thick.png");
  ASSERT_GT(thin, 100u);
  const double ratio = static_cast<double>(thick) / static_cast<double>(thin);
  EXPECT_GT(ratio, 3.5) << thin << " -> " << thick << " red pixels";
  EXPECT_LT(ratio, 9.0) << thin << " -> " << thick << " red pixels";
}

// ---------------------------------------------------------------------------------------------
// Colour by value and the legend

// The pixel near (x, y) that is most colourful (largest max - min channel): the track's, over
// the grey ground.
std::optional<Rgb> most_colourful_near(const Picture& picture, double x, double y, int radius) {
  std::optional<Rgb> best;
  int best_chroma = -1;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double px = std::round(x) + dx, py = std::round(y) + dy;
      if (!picture.inside(px, py)) continue;
      const Rgb p = picture.at(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py));
      const int chroma = std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b});
      if (chroma > best_chroma) best_chroma = chroma, best = p;
    }
  return best;
}

// Chromaticity (r, g, b over their sum): what lighting leaves of a colour.
glm::dvec3 chromaticity(double r, double g, double b) {
  const double sum = std::max(r + g + b, 1e-9);
  return {r / sum, g / sum, b / sum};
}
glm::dvec3 chromaticity(const Rgb& p) { return chromaticity(p.r, p.g, p.b); }
glm::dvec3 chromaticity(const glm::vec3& c) { return chromaticity(c.r, c.g, c.b); }

// The average chromaticity of the most colourful pixels near points [first, last) of a track.
glm::dvec3 track_chromaticity(const Picture& picture, const scene::Camera& camera, const std::vector<GpxPoint>& points,
                              std::size_t first, std::size_t last) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (std::size_t i = first; i < last; ++i) {
    const auto at = project(camera, points[i]);
    if (!at || !picture.inside(at->x_px, at->y_px)) continue;
    if (const auto p = most_colourful_near(picture, at->x_px, at->y_px, 2)) {
      sum += chromaticity(*p);
      ++n;
    }
  }
  EXPECT_GT(n, 5) << "points " << first << ".." << last << " in the picture";
  return n > 0 ? sum / double(n) : sum;
}

TEST(TrackRenderCli, SpeedThatDoublesShowsBothEndsOfTheColormap) {
  RenderEnv env;
  const auto points = doubling_speed_hike();
  const std::string gpx = env.write_gpx("doubling.gpx", {{"Doubling", {points}}});
  const Picture picture =
      render_to(env, shell_quote(gpx) + kPicture + " --color-by speed --width 8px --legend off", "speed.png");
  ASSERT_EQ(picture.width, kWidth);
  keep(env, "speed.png");
  const scene::Camera camera = framing_camera(points, kWidth, kHeight);
  // Away from the change (the speed window and smoothing blur it over a few points).
  const glm::dvec3 slow = track_chromaticity(picture, camera, points, 5, 33);
  const glm::dvec3 fast = track_chromaticity(picture, camera, points, 47, 77);
  const glm::dvec3 low = chromaticity(scene::colormap_color(scene::Colormap::turbo, 0.0f));
  const glm::dvec3 high = chromaticity(scene::colormap_color(scene::Colormap::turbo, 1.0f));
  EXPECT_LT(glm::distance(slow, low), glm::distance(slow, high))
      << "slow part " << slow.r << "," << slow.g << "," << slow.b << " is not turbo's low end";
  EXPECT_LT(glm::distance(fast, high), glm::distance(fast, low))
      << "fast part " << fast.r << "," << fast.g << "," << fast.b << " is not turbo's high end";
  EXPECT_GT(glm::distance(slow, fast), 0.2) << "two distinct colours";
  // Turbo's low end is violet (blue over red), its high end dark red.
  EXPECT_GT(slow.b, slow.g);
  EXPECT_GT(fast.r, fast.b + 0.2);
  EXPECT_GT(fast.r, fast.g + 0.2);
}

// Where the legend of these tracks goes in a kWidth x kHeight picture, found by drawing the same
// legend on a blank image.
scene::LegendLayout legend_layout(const std::string& gpx, const std::vector<std::string>& style_args) {
  app::StyleArgs args;
  for (std::size_t i = 0; i + 1 < style_args.size(); i += 2)
    if (style_args[i] == "--color-by") args.color_by = style_args[i + 1];
  const scene::Style style = app::parse_style(args);
  const track::ReadResult read = track::load_track_file(gpx);
  EXPECT_TRUE(read.ok());
  scene::CollectedDiagnostics ignored;
  scene::TrackSet tracks;
  for (scene::Track& t : scene::build_tracks({{gpx, read.file}}, style.tracks, {}, ignored)) tracks.add(std::move(t));
  scene::RgbaImage blank{kWidth, kHeight, std::vector<std::uint8_t>(std::size_t{kWidth} * kHeight * 4, 128)};
  scene::TextRasterizer text;
  scene::LegendLayout layout;
  if (const auto legend = scene::color_legend_for(style.tracks, scene::color_range(tracks, style)))
    layout = scene::draw_color_legend(blank, text, *legend);
  else
    layout = scene::draw_track_key(blank, text, scene::track_key_for(style.tracks, tracks));
  EXPECT_TRUE(layout.drawn) << "the legend fits a " << kWidth << "x" << kHeight << " picture";
  return layout;
}

// The panel it takes.
scene::PixelRect legend_panel(const std::string& gpx, const std::vector<std::string>& style_args) {
  return legend_layout(gpx, style_args).panel;
}

// The options of an explicit camera where the framing without a legend puts it. The legend never
// moves an explicit camera, so pictures with and without it differ in its panel only.
std::string camera_options(const std::vector<GpxPoint>& points) {
  const scene::LookAt l = framing(points, kWidth, kHeight).look_at;
  char text[256];
  std::snprintf(text, sizeof text, " --look-at %.9f,%.9f,%.3f --distance %.3f --heading %.6f --pitch %.6f",
                l.target.lat_deg, l.target.lon_deg, l.target.height_m, l.distance_m, l.heading_deg, l.pitch_deg);
  return text;
}

// Pixels that differ between two pictures: how many inside `panel`, how many outside.
struct Difference {
  std::size_t inside = 0, outside = 0, darker_inside = 0;
};
Difference compare(const Picture& on, const Picture& off, const scene::PixelRect& panel) {
  Difference d;
  for (std::uint32_t y = 0; y < on.height; ++y)
    for (std::uint32_t x = 0; x < on.width; ++x) {
      const Rgb a = on.at(x, y), b = off.at(x, y);
      if (a.r == b.r && a.g == b.g && a.b == b.b) continue;
      if (panel.contains(int(x), int(y))) {
        ++d.inside;
        d.darker_inside += (a.r + a.g + a.b) < (b.r + b.g + b.b) ? 1 : 0;
      } else {
        ++d.outside;
      }
    }
  return d;
}

TEST(TrackRenderCli, LegendTakesTheBottomLeftPanelOnly) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("doubling.gpx", {{"Doubling", {doubling_speed_hike()}}});
  const std::string common =
      shell_quote(gpx) + kPicture + camera_options(doubling_speed_hike()) + " --color-by speed --legend ";
  const Picture on = render_to(env, common + "on", "legend_on.png");
  const Picture off = render_to(env, common + "off", "legend_off.png");
  ASSERT_EQ(on.width, kWidth);
  ASSERT_EQ(off.width, kWidth);
  keep(env, "legend_on.png");
  const scene::PixelRect panel = legend_panel(gpx, {"--color-by", "speed"});
  EXPECT_LT(panel.x, int(kWidth / 4));
  EXPECT_GT(panel.bottom(), int(kHeight * 3 / 4));
  const Difference d = compare(on, off, panel);
  EXPECT_EQ(d.outside, 0u) << "the legend changed pixels outside its panel";
  const std::size_t area = std::size_t(panel.width) * std::size_t(panel.height);
  EXPECT_GT(d.inside, area / 2) << "the panel covers its area";
  EXPECT_GT(d.darker_inside, d.inside / 2) << "a dark panel";
}

// ---------------------------------------------------------------------------------------------
// Several tracks

TEST(TrackRenderCli, SeveralSolidTracksGetPaletteColoursAndAKey) {
  RenderEnv env;
  std::vector<std::vector<GpxPoint>> lines;
  for (int i = 0; i < 3; ++i) lines.push_back(east_line(kLat, kLon, 0.0, 61, 25.0, kT0, 10.0, 1000.0, 400.0 * i));
  const std::string gpx =
      env.write_gpx("three.gpx", {{"Alpha", {lines[0]}}, {"Beta", {lines[1]}}, {"Gamma", {lines[2]}}});
  std::vector<GpxPoint> all;
  for (const auto& l : lines) all.insert(all.end(), l.begin(), l.end());
  // Without labels: the tracks' names keep out of the key, so they would move with it.
  const std::string common = shell_quote(gpx) + kPicture + camera_options(all) + " --width 8px --no-labels --legend ";
  const Picture on = render_to(env, common + "on", "three_on.png");
  const Picture off = render_to(env, common + "off", "three_off.png");
  ASSERT_EQ(on.width, kWidth);
  ASSERT_EQ(off.width, kWidth);
  keep(env, "three_on.png");

  // Each track, away from the legend, in its palette colour rather than another's.
  const scene::Camera camera = framing_camera(all, kWidth, kHeight);
  const scene::PixelRect panel = legend_panel(gpx, {});
  for (std::size_t t = 0; t < 3; ++t) {
    std::vector<GpxPoint> right_half(lines[t].begin() + 35, lines[t].end() - 3);
    const auto at = project(camera, right_half.front());
    ASSERT_TRUE(at.has_value());
    ASSERT_FALSE(panel.contains(int(at->x_px), int(at->y_px))) << "track " << t << " sampled under the key";
    const glm::dvec3 seen = track_chromaticity(off, camera, right_half, 0, right_half.size());
    for (std::size_t other = 0; other < 3; ++other) {
      if (other == t) continue;
      EXPECT_LT(glm::distance(seen, chromaticity(scene::palette_color(t))),
                glm::distance(seen, chromaticity(scene::palette_color(other))))
          << "track " << t << " looks like palette colour " << other;
    }
  }

  // The key: a dark panel at the bottom left, nothing else changed.
  const Difference d = compare(on, off, panel);
  EXPECT_EQ(d.outside, 0u);
  EXPECT_GT(d.inside, std::size_t(panel.width) * std::size_t(panel.height) / 2);
}

// Two red tracks, a long one and a short one south of its west end: the framing without a legend
// (looking north) puts the short one low left, where the key of their names goes. Framed for
// the key, they stay out of its panel, whole in the picture and as large as without it.
TEST(TrackRenderCli, FramingKeepsTheTracksOutOfTheLegend) {
  RenderEnv env;
  const auto north = east_line(kLat, kLon, 0.0, 61, 50.0, kT0, 10.0, 1000.0);
  const auto south = east_line(kLat, kLon, 0.0, 21, 25.0, kT0, 10.0, 1000.0, -1500.0);
  const std::string gpx = env.write_gpx("two.gpx", {{"North", {north}}, {"South", {south}}});
  const std::string common = shell_quote(gpx) + kPicture + " --color '#ff0000' --width 6px --legend ";
  const Picture on = render_to(env, common + "on", "clear_on.png");
  const Picture off = render_to(env, common + "off", "clear_off.png");
  ASSERT_EQ(on.width, kWidth);
  ASSERT_EQ(off.width, kWidth);
  keep(env, "clear_on.png");
  keep(env, "clear_off.png");
  const scene::LegendLayout key = legend_layout(gpx, {});
  ASSERT_EQ(key.swatches.size(), 2u);

  // Without the legend in mind, the south track would lie under the key: this test can fail.
  std::vector<GpxPoint> all = north;
  all.insert(all.end(), south.begin(), south.end());
  const scene::Camera centred = framing_camera(all, kWidth, kHeight);
  std::size_t under = 0;
  for (const GpxPoint& p : south) {
    const auto at = project(centred, p);
    if (at && key.panel.contains(int(at->x_px), int(at->y_px))) ++under;
  }
  ASSERT_GT(under, 3u) << "the tracks do not reach the key's corner: the test proves nothing";

  // Nothing of the tracks in the key's panel: no red seen through it, the red swatches aside.
  const auto in_swatch = [&](std::uint32_t x, std::uint32_t y) {
    return std::any_of(key.swatches.begin(), key.swatches.end(), [&](const scene::PixelRect& r) {
      return scene::PixelRect{r.x - 1, r.y - 1, r.width + 2, r.height + 2}.contains(int(x), int(y));
    });
  };
  std::size_t red_in_panel = 0, red_outside = 0, red_on_edge = 0;
  for (std::uint32_t y = 0; y < on.height; ++y)
    for (std::uint32_t x = 0; x < on.width; ++x) {
      const Rgb p = on.at(x, y);
      if (key.panel.contains(int(x), int(y))) {
        red_in_panel += reddish(p) && !in_swatch(x, y) ? 1 : 0;
        continue;
      }
      red_outside += red(p) ? 1 : 0;
      if (x < 2 || y < 2 || x + 2 >= on.width || y + 2 >= on.height) red_on_edge += red(p) ? 1 : 0;
    }
  EXPECT_EQ(red_in_panel, 0u) << "track pixels under the legend";
  // Whole in the picture, at about the size the picture without the legend shows them: none of
  // their pixels lost (a track under the panel would lose a fifth of them here); a few more are
  // fine (the camera moved, so the tubes' shading and perspective changed a little).
  EXPECT_EQ(red_on_edge, 0u) << "a track runs off the picture";
  const std::size_t red_off = count(off, red);
  EXPECT_GT(red_off, 400u);
  EXPECT_GT(double(red_outside), 0.9 * double(red_off));
  EXPECT_LT(double(red_outside), 1.25 * double(red_off));
}

TEST(TrackRenderCli, OneSolidTrackHasNoKey) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string common = shell_quote(gpx) + kPicture + " --legend ";
  const Picture on = render_to(env, common + "on", "one_on.png");
  const Picture off = render_to(env, common + "off", "one_off.png");
  ASSERT_EQ(on.width, kWidth);
  EXPECT_EQ(on.rgba, off.rgba) << "--legend on drew something for one solid track";
}

// ---------------------------------------------------------------------------------------------
// Real terrain

// The Mödling walk over the 1 km Austria DEM: the coarse DEM lies above the path in the valleys,
// so part of the track is hidden; drawn translucent with --occlusion on, not at all with off.
TEST(TrackRenderCli, OcclusionOnShowsTheHiddenPartsOfTheTrack) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/austria_1km_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(walk, "gpx/alpinemaps_husarentempel.gpx");
  RenderEnv env;
  const std::string common = shell_quote(walk.string()) + " --terrain " + shell_quote(dem.string()) +
                             " --no-ssao --no-atmosphere --size 320x180 --color '#ff0000' --width 4px --occlusion ";
  const Picture on = render_to(env, common + "on", "occlusion_on.png");
  const Picture off = render_to(env, common + "off", "occlusion_off.png");
  ASSERT_EQ(on.width, kWidth);
  ASSERT_EQ(off.width, kWidth);
  keep(env, "occlusion_on.png");
  keep(env, "occlusion_off.png");
  const std::size_t red_on = count(on, reddish), red_off = count(off, reddish);
  EXPECT_GT(count(off, red), 100u) << "the visible parts are drawn either way";
  EXPECT_GT(red_on, red_off + red_off / 5) << red_off << " -> " << red_on << " track-coloured pixels";
  // Occlusion only adds: no pixel is track-coloured without it and not with it.
  std::size_t lost = 0;
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kWidth; ++x) lost += reddish(off.at(x, y)) && !reddish(on.at(x, y)) ? 1 : 0;
  EXPECT_LT(lost, red_off / 50 + 2);
}

// The Interlaken flight with --curtain: the wall hangs from the track down to the terrain, so
// the pixels it changes lie below the track's image, column by column.
TEST(TrackRenderCli, CurtainChangesThePixelsBelowAFlight) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  RenderEnv env;
  const std::string common = shell_quote(flight.string()) + " --terrain " + shell_quote(dem.string()) +
                             " --no-ssao --no-atmosphere --size 320x180 --color '#ff0000' --width 3px";
  const Picture plain = render_to(env, common, "flight.png");
  const Picture curtain = render_to(env, common + " --curtain", "curtain.png");
  ASSERT_EQ(plain.width, kWidth);
  ASSERT_EQ(curtain.width, kWidth);
  keep(env, "flight.png");
  keep(env, "curtain.png");

  // The track's topmost image row per column (the polyline between projected points).
  const track::ReadResult read = track::load_track_file(flight.string());
  ASSERT_TRUE(read.ok());
  std::vector<GpxPoint> points;
  for (const auto& t : read.file.tracks)
    for (const auto& s : t.segments)
      for (const auto& p : s.points) points.push_back({p.lat, p.lon, p.ele, p.time});
  ASSERT_GT(points.size(), 10u);
  const scene::Camera camera = framing_camera(points, kWidth, kHeight);
  std::vector<double> top(kWidth, 1e9);
  std::optional<terrain::ScreenPoint> previous;
  for (const GpxPoint& p : points) {
    const auto at = project(camera, p);
    if (at && previous) {
      const int steps = 1 + int(std::ceil(std::abs(at->x_px - previous->x_px)));
      for (int k = 0; k <= steps; ++k) {
        const double f = double(k) / steps;
        const double x = previous->x_px + f * (at->x_px - previous->x_px);
        const double y = previous->y_px + f * (at->y_px - previous->y_px);
        const long column = std::lround(x);
        if (column >= 0 && column < long(kWidth)) top[std::size_t(column)] = std::min(top[std::size_t(column)], y);
      }
    }
    previous = at;
  }
  std::size_t changed = 0, below = 0;
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const Rgb a = plain.at(x, y), b = curtain.at(x, y);
      if (std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) <= 6) continue;
      ++changed;
      below += y + 3.0 >= top[x] ? 1 : 0;
    }
  EXPECT_GT(changed, 300u) << "the curtain is visible";
  EXPECT_GE(below, changed * 95 / 100) << below << " of " << changed << " changed pixels below the track";
}

// ---------------------------------------------------------------------------------------------
// Odd tracks

TEST(TrackRenderCli, OnePointAndARepeatedPointRender) {
  RenderEnv env;
  GpxPoint one = offset_point(kLat, kLon, 0.0, 0.0);
  one.ele = 1000.0;
  one.time = kT0;
  GpxPoint again = one;
  again.time = kT0 + 10.0;
  const std::string single = env.write_gpx("one.gpx", {{"One", {{one}}}});
  const std::string twice = env.write_gpx("twice.gpx", {{"Twice", {{one, one}}}});
  const std::string still = env.write_gpx("still.gpx", {{"Still", {{one, again}}}});
  for (const std::string& gpx : {single, twice, still}) {
    const Picture picture = render_to(env, shell_quote(gpx) + kPicture + " --color '#ff0000' --width 10px", "odd.png");
    keep(env, "odd.png");
    ASSERT_EQ(picture.width, kWidth) << gpx;
    // A sphere where the point projects.
    const auto at = project(framing_camera({one}, kWidth, kHeight), one);
    ASSERT_TRUE(at.has_value());
    EXPECT_TRUE(any_near(picture, at->x_px, at->y_px, 3, red)) << gpx;
  }
}

TEST(TrackRenderCli, EmptySegmentsAreSkipped) {
  RenderEnv env;
  const auto points = straight_hike();
  const std::string gpx = env.write_gpx("empty_segment.gpx", {{"Hike", {{}, points, {}}}});
  const Picture picture = render_to(env, shell_quote(gpx) + kPicture + " --color '#ff0000'", "empty_segment.png");
  ASSERT_EQ(picture.width, kWidth);
  EXPECT_GT(count(picture, red), 300u);

  // A file whose only segment is empty has nothing to draw: a clear error, not a crash.
  const std::string nothing = env.write_gpx("nothing.gpx", {{"Nothing", {{}}}});
  const auto r = run_command(env.prefix() + shell_quote(nothing) + kPicture + " -o " +
                             shell_quote(env.file("nothing.png")) + " 2>&1");
  EXPECT_TRUE(r.status == 0 || r.status == 1) << r.out;
  if (r.status != 0) {
    EXPECT_NE(r.out.find("trailray: error:"), std::string::npos) << r.out;
  }
}

// Two segments on one line with 1 km between them: nothing is drawn across the gap.
TEST(TrackRenderCli, AGapBetweenSegmentsIsNotBridged) {
  RenderEnv env;
  const auto first = east_line(kLat, kLon, 0.0, 41, 25.0, kT0, 10.0, 1000.0);
  const auto second = east_line(kLat, kLon, 2000.0, 41, 25.0, kT0 + 3600.0, 10.0, 1000.0);
  const std::string gpx = env.write_gpx("gap.gpx", {{"Gap", {first, second}}});
  const Picture picture = render_to(env, shell_quote(gpx) + kPicture + " --color '#ff0000' --width 6px", "gap.png");
  ASSERT_EQ(picture.width, kWidth);
  keep(env, "gap.png");
  std::vector<GpxPoint> all = first;
  all.insert(all.end(), second.begin(), second.end());
  const scene::Camera camera = framing_camera(all, kWidth, kHeight);
  // The facing ends are drawn ...
  for (const GpxPoint& end : {first[37], second[3]}) {
    const auto at = project(camera, end);
    ASSERT_TRUE(at.has_value());
    EXPECT_TRUE(any_near(picture, at->x_px, at->y_px, 2, red)) << at->x_px << "," << at->y_px;
  }
  // ... and the line between them is not, from 200 m past one end to 200 m before the other.
  for (double east = 1200.0; east <= 1800.0; east += 50.0) {
    GpxPoint mid = offset_point(kLat, kLon, east, 0.0);
    mid.ele = 1000.0;
    const auto at = project(camera, mid);
    ASSERT_TRUE(at.has_value());
    EXPECT_FALSE(any_near(picture, at->x_px, at->y_px, 2, red)) << "red at " << east << " m, in the gap";
  }
}

}  // namespace
}  // namespace trailray::test
