// `trailray elevation` as a user runs it: the same numbers from a GeoTIFF, a tile folder, an
// MBTiles file and an HTTP server; JSON and CSV shapes; --replace; errors and offline use.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/run_command.hpp"
#include "terrain/dem_pyramid.hpp"
#include "terrain/local_tile_server.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;
using trailray::test::TempFile;

namespace {

// Runs trailray with a private config and cache folder (a user's own must not leak in), stderr
// folded into the output when `with_stderr`.
struct Env {
  TempDir home;
  std::string prefix() const {
    return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
           " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) + " TRAILRAY_CONFIG= " +
           shell_quote(TRAILRAY_BINARY) + " ";
  }
};

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* kWalk = R"(<gpx version="1.1" creator="test"><trk><name>Walk &amp; talk</name><trkseg>
<trkpt lat="46.7000" lon="7.8500"><ele>900</ele><time>2024-06-01T10:00:00Z</time></trkpt>
<trkpt lat="46.7010" lon="7.8510"><ele>950</ele><time>2024-06-01T10:05:00Z</time></trkpt>
<trkpt lat="46.7020" lon="7.8520"><time>2024-06-01T10:10:00Z</time></trkpt>
<trkpt lat="10.0" lon="10.0"><ele>5</ele></trkpt>
</trkseg></trk></gpx>)";

}  // namespace

TEST(ElevationCli, SameNumbersFromGeoTiffFolderMbtilesAndHttp) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_25m_lv95.tif");
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  const auto read = trailray::track::load_track_file(flight.string());
  ASSERT_TRUE(read.ok());
  trailray::geo::LatLonBounds box;
  for (const auto& p : read.file.tracks.at(0).segments.at(0).points) box.add(p.lat, p.lon);
  trailray::test::DemPyramid pyramid;
  trailray::test::build_dem_pyramid(pyramid, dem, box, 15);
  trailray::test::http::LocalTileServer server(pyramid.xyz_folder);
  Env env;

  std::map<std::string, json> docs;
  for (const auto& [name, source] : std::map<std::string, std::string>{
           {"geotiff", dem.string()},
           {"folder", pyramid.xyz_folder.string()},
           {"mbtiles", pyramid.mbtiles.string()},
           {"http", server.url("/tiles/{z}/{x}/{y}.png")}}) {
    const std::string extra = name == "http" ? " --terrain-zoom 15" : "";
    auto r = run_command(env.prefix() + "elevation --json --terrain " + shell_quote(source) + extra + " " +
                         shell_quote(flight.string()));
    ASSERT_EQ(r.status, 0) << name << ": " << r.out;
    docs[name] = json::parse(r.out);
  }
  const json& tiff = docs["geotiff"];
  EXPECT_EQ(tiff["path"], flight.string());
  ASSERT_EQ(tiff["points"].size(), read.file.tracks[0].point_count());
  const json& first = tiff["points"][0];
  for (const char* key : {"lat", "lon", "ele_m", "terrain_m", "agl_m"}) EXPECT_TRUE(first.contains(key)) << key;
  // The manifest's georeferencing check: the take-off is at 1587 m on this DEM.
  EXPECT_NEAR(first["terrain_m"].get<double>(), 1587.0, 3.0);
  EXPECT_NEAR(first["agl_m"].get<double>(), first["ele_m"].get<double>() - first["terrain_m"].get<double>(), 0.011);
  const json& s = tiff["summary"];
  for (const char* key : {"mean_offset_m", "median_offset_m", "rmse_m", "points_below_ground"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_GT(s["mean_offset_m"].get<double>(), 20.0);  // a flight, well above ground on average

  for (const char* name : {"folder", "mbtiles", "http"}) {
    const json& d = docs[name];
    // Tile sources serve identical bytes: identical output.
    EXPECT_EQ(d["points"], docs["folder"]["points"]) << name;
    EXPECT_NEAR(d["summary"]["mean_offset_m"].get<double>(), s["mean_offset_m"].get<double>(), 0.05) << name;
    EXPECT_NEAR(d["summary"]["median_offset_m"].get<double>(), s["median_offset_m"].get<double>(), 0.05) << name;
    EXPECT_NEAR(d["summary"]["rmse_m"].get<double>(), s["rmse_m"].get<double>(), 0.05) << name;
    EXPECT_NEAR(d["summary"]["points_below_ground"].get<double>(), s["points_below_ground"].get<double>(), 3) << name;
  }

  // Offline, the second run needs nothing from the server: the disk cache has every tile.
  server.stop();
  auto r = run_command(env.prefix() + "elevation --json --offline --terrain-zoom 15 --terrain " +
                       shell_quote(server.url("/tiles/{z}/{x}/{y}.png")) + " " + shell_quote(flight.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(json::parse(r.out)["points"], docs["http"]["points"]);
}

TEST(ElevationCli, CsvAndTableAndMissingValues) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TempFile walk("walk.gpx", kWalk);
  Env env;
  auto csv = run_command(env.prefix() + "elevation --csv --terrain " + shell_quote(dem.string()) + " " + walk.str());
  ASSERT_EQ(csv.status, 0) << csv.out;
  std::istringstream lines(csv.out);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], "track,segment,lat,lon,ele_m,terrain_m,agl_m");
  EXPECT_TRUE(rows[3].find(",,") != std::string::npos) << rows[3];       // no recorded elevation
  EXPECT_EQ(rows[4].substr(rows[4].size() - 6), "5.00,,") << rows[4];  // outside the DEM: no terrain

  auto table = run_command(env.prefix() + "elevation --terrain " + shell_quote(dem.string()) + " " + walk.str() + " 2>&1");
  ASSERT_EQ(table.status, 0) << table.out;
  EXPECT_NE(table.out.find("4 (3 with elevation, 3 with terrain)"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("no data at 1 of 4 points"), std::string::npos) << table.out;

  auto none = run_command(env.prefix() + "elevation --json --terrain none " + walk.str());
  ASSERT_EQ(none.status, 0);
  EXPECT_TRUE(json::parse(none.out)["summary"]["mean_offset_m"].is_null());
}

TEST(ElevationCli, ReplaceWritesACopyAndNeverTheInput) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TempFile walk("walk.gpx", kWalk);
  Env env;
  const auto out = walk.path().parent_path() / "out.gpx";
  const std::string base = env.prefix() + "elevation --terrain " + shell_quote(dem.string()) + " ";
  auto r = run_command(base + "--replace -o " + shell_quote(out.string()) + " " + walk.str() + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(read_file(walk.path()), kWalk);
  const auto copy = trailray::track::load_track_file(out.string());
  ASSERT_TRUE(copy.ok());
  const auto& pts = copy.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_EQ(copy.file.tracks[0].name, "Walk & talk");
  auto terrain = run_command(base + "--json " + walk.str());
  const json t = json::parse(terrain.out);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(pts[i].ele, t["points"][i]["terrain_m"].get<double>(), 0.006) << i;
  EXPECT_EQ(pts[3].ele, 5.0);  // no terrain there: the recorded value stays
  EXPECT_TRUE(pts[0].has_time());

  auto again = run_command(base + "--replace -o " + shell_quote(out.string()) + " " + walk.str() + " 2>&1");
  EXPECT_EQ(again.status, 1);
  EXPECT_NE(again.out.find("already exists"), std::string::npos) << again.out;
  auto forced = run_command(base + "--replace --force -o " + shell_quote(out.string()) + " " + walk.str());
  EXPECT_EQ(forced.status, 0);
  auto self = run_command(base + "--replace --force -o " + walk.str() + " " + walk.str() + " 2>&1");
  EXPECT_EQ(self.status, 1);
  EXPECT_NE(self.out.find("never modifies its input"), std::string::npos) << self.out;
  EXPECT_EQ(read_file(walk.path()), kWalk);
  auto no_output = run_command(base + "--replace " + walk.str() + " 2>&1");
  EXPECT_EQ(no_output.status, 2) << no_output.out;
}

TEST(ElevationCli, BadSourcesAndConfigGiveClearErrors) {
  TempFile walk("walk.gpx", kWalk);
  Env env;
  auto missing = run_command(env.prefix() + "elevation --terrain /no/such/dem.tif " + walk.str() + " 2>&1");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("/no/such/dem.tif"), std::string::npos) << missing.out;

  TempFile text("notes.tif", "just some text\n");
  auto not_raster = run_command(env.prefix() + "elevation --terrain " + text.str() + " " + walk.str() + " 2>&1");
  EXPECT_EQ(not_raster.status, 1);
  EXPECT_NE(not_raster.out.find(text.str()), std::string::npos) << not_raster.out;

  TempFile config("config.toml", "[terrain]\nsource = \"none\"\nmax_zom = 3\n");
  auto bad = run_command(env.prefix() + "elevation --config " + config.str() + " " + walk.str() + " 2>&1");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.out.find(config.str() + ":3:1: unknown key `max_zom` in [terrain]"), std::string::npos) << bad.out;

  // Offline with nothing cached: no data, a warning, no network.
  auto offline = run_command(env.prefix() + "elevation --offline --json --terrain " +
                             shell_quote("http://127.0.0.1:9/{z}/{x}/{y}.png") + " " + walk.str() + " 2>&1");
  EXPECT_EQ(offline.status, 0) << offline.out;
  EXPECT_NE(offline.out.find("has no data at any point"), std::string::npos) << offline.out;
}

TEST(ElevationCli, EveryTileFailingIsAnErrorNotAnAnswer) {
  // A tile server that refuses every connection (nothing listens on port 1): no height at all.
  Env env;
  TempFile walk("walk.gpx", kWalk);
  const auto r = run_command(env.prefix() + "elevation " + shell_quote(walk.path().string()) +
                             " --terrain 'http://127.0.0.1:1/{z}/{x}/{y}.png' 2>&1");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("no terrain height could be had"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failed"), std::string::npos) << r.out;
}

namespace {

// A straight walk of `n` points between two places, every point at `ele` (NaN: no elevation).
std::string straight_walk(std::pair<double, double> a, std::pair<double, double> b, int n, double ele) {
  std::string gpx = "<gpx version=\"1.1\" creator=\"test\"><trk><name>Forest</name><trkseg>\n";
  for (int i = 0; i < n; ++i) {
    const double f = i / double(n - 1);
    gpx += "<trkpt lat=\"" + std::to_string(a.first + (b.first - a.first) * f) + "\" lon=\"" +
           std::to_string(a.second + (b.second - a.second) * f) + "\">" +
           (std::isnan(ele) ? std::string() : "<ele>" + std::to_string(ele) + "</ele>") + "</trkpt>\n";
  }
  return gpx + "</trkseg></trk></gpx>\n";
}

}  // namespace

// --surface on a real lidar pair of one forest (shared/data/dem/SURFACE_PAIR.json: a terrain and a
// surface model, 1 m, and a line from an opening through 20 m canopy to another opening): the
// walk's ends are open, its middle under cover; a glider far above is open everywhere, a tunnel
// below the ground everywhere; canopy_m is surface_m - terrain_m; CSV and table say the same.
TEST(ElevationCli, SurfaceModelTellsTheForestFromTheOpen) {
  TRAILRAY_REQUIRE_DATA(pair_file, "dem/SURFACE_PAIR.json");
  const json pair = json::parse(read_file(pair_file));
  const std::string dtm = (pair_file.parent_path() / pair["dtm"].get<std::string>()).string();
  const std::string dsm = (pair_file.parent_path() / pair["dsm"].get<std::string>()).string();
  const std::pair<double, double> a{pair["line"][0][0], pair["line"][0][1]}, b{pair["line"][1][0], pair["line"][1][1]};
  Env env;
  const std::string models = " --terrain " + shell_quote(dtm) + " --surface " + shell_quote(dsm) + " ";

  TempFile walk("walk.gpx", straight_walk(a, b, 101, std::nan("")));
  auto r = run_command(env.prefix() + "elevation --json" + models + walk.str());
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["surface"], dsm);
  const json& points = doc["points"];
  ASSERT_EQ(points.size(), 101u);
  EXPECT_EQ(points[0]["cover"], "open");
  EXPECT_EQ(points[100]["cover"], "open");
  EXPECT_EQ(points[50]["cover"], "covered");
  EXPECT_GT(points[50]["canopy_m"].get<double>(), 10.0);
  for (const json& p : points)
    EXPECT_NEAR(p["canopy_m"].get<double>(), p["surface_m"].get<double>() - p["terrain_m"].get<double>(), 0.011);
  const json& s = doc["summary"];
  EXPECT_EQ(s["points_open"].get<int>() + s["points_covered"].get<int>() + s["points_cover_below_ground"].get<int>(),
            101);
  EXPECT_EQ(s["points_cover_below_ground"], 0);
  EXPECT_GT(s["covered_share"].get<double>(), 0.6);
  EXPECT_LT(s["covered_share"].get<double>(), 0.97);

  TempFile glider("glider.gpx", straight_walk(a, b, 21, 700.0));  // the ground is at 350-370 m
  const json high = json::parse(run_command(env.prefix() + "elevation --json" + models + glider.str()).out);
  EXPECT_EQ(high["summary"]["points_open"], 21);
  EXPECT_EQ(high["summary"]["covered_share"], 0.0);
  TempFile tunnel("tunnel.gpx", straight_walk(a, b, 21, 250.0));
  const json low = json::parse(run_command(env.prefix() + "elevation --json" + models + tunnel.str()).out);
  EXPECT_EQ(low["summary"]["points_cover_below_ground"], 21);

  auto csv = run_command(env.prefix() + "elevation --csv" + models + walk.str());
  ASSERT_EQ(csv.status, 0);
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), "track,segment,lat,lon,ele_m,terrain_m,agl_m,surface_m,canopy_m,cover");
  EXPECT_NE(csv.out.find(",covered\n"), std::string::npos);
  auto table = run_command(env.prefix() + "elevation" + models + walk.str());
  ASSERT_EQ(table.status, 0);
  EXPECT_NE(table.out.find("under cover"), std::string::npos) << table.out;
}
