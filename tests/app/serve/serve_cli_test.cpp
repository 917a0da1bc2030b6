// `trailray serve` as a user (and a hostile client) meets it: the process runs, the tests talk raw
// HTTP to it over 127.0.0.1: the web app's files, the configuration, the tracks byte for byte,
// terrain tiles equal to the terrain layer's, traversal attempts, unknown paths and methods,
// oversized requests, slow clients, the connection limit, bad tracks, a port in use, signals.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/raw_http.hpp"
#include "app/run_command.hpp"
#include "app/serve_process.hpp"
#include "geo/tile_id.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/local_tile_server.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::ServeProcess;
using trailray::test::TempDir;
namespace http = trailray::test::http_client;
namespace fs = std::filesystem;

namespace {

const char* kGpx = R"(<?xml version="1.0"?>
<gpx version="1.1" creator="test"><trk><name>Walk</name><trkseg>
<trkpt lat="46.7000" lon="7.8500"><ele>900</ele><time>2024-06-01T10:00:00Z</time></trkpt>
<trkpt lat="46.7010" lon="7.8510"><ele>950</ele><time>2024-06-01T10:05:00Z</time></trkpt>
</trkseg></trk></gpx>
)";

void write(const fs::path& p, const std::string& content) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << content;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A web root with an app in it, and a secret beside it that must never be served.
struct Site {
  TempDir dir;
  fs::path web = dir.path() / "web";
  fs::path secret = dir.path() / "secret.txt";
  fs::path track = dir.path() / "tracks" / "walk & talk.gpx";
  Site() {
    write(web / "index.html", "<!DOCTYPE html><title>app</title>");
    write(web / "app.js", "console.log('app');");
    write(web / "app.wasm", std::string("\0asm\1\0\0\0", 8));
    write(web / "style.css", "body{}");
    write(web / "sub" / "index.html", "<p>sub</p>");
    write(web / ".hidden", "hidden");
    write(secret, "TOP SECRET");
    write(track, kGpx);
    fs::create_symlink(secret, web / "link.txt");
  }
};

std::vector<std::string> base_args(const Site& site) {
  return {"--port", "0", "--terrain", "none", "--imagery", "none", "--web-root", site.web.string()};
}

}  // namespace

TEST(ServeCli, ServesTheAppTheConfigAndTheTracksByteForByte) {
  Site site;
  auto args = base_args(site);
  args.insert(args.end(), {"--color", "#ff00ff", "--color-by", "vspeed", "--no-ssao", "--look-at", "46.7,7.85,900",
                           "--heading", "30", site.track.string()});
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.first_line() << serve.stderr_text();
  EXPECT_EQ(serve.first_line(), "trailray: serving on http://127.0.0.1:" + std::to_string(serve.port()) + "/");

  const auto page = http::get(serve.port(), "/");
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.body, "<!DOCTYPE html><title>app</title>");
  EXPECT_EQ(page.header("content-type"), "text/html; charset=utf-8");
  EXPECT_EQ(http::get(serve.port(), "/app.js").header("content-type"), "text/javascript; charset=utf-8");
  const auto wasm = http::get(serve.port(), "/app.wasm");
  EXPECT_EQ(wasm.header("content-type"), "application/wasm");
  EXPECT_EQ(wasm.body, std::string("\0asm\1\0\0\0", 8));
  EXPECT_EQ(http::get(serve.port(), "/style.css").header("content-type"), "text/css; charset=utf-8");
  EXPECT_EQ(http::get(serve.port(), "/sub/").body, "<p>sub</p>");
  const auto head = http::get(serve.port(), "/app.js", "HEAD");
  EXPECT_EQ(head.status, 200);
  EXPECT_EQ(head.header("content-length"), "19");
  EXPECT_TRUE(head.body.empty());

  const auto config = http::get(serve.port(), "/api/config.json");
  ASSERT_EQ(config.status, 200);
  EXPECT_EQ(config.header("content-type"), "application/json");
  const json c = json::parse(config.body);
  EXPECT_TRUE(c["terrain"].is_null());
  EXPECT_TRUE(c["imagery"].is_null());
  EXPECT_EQ(c["options"], json({{"color", "#ff00ff"},
                                {"color-by", "vspeed"},
                                {"no-ssao", true},
                                {"look-at", "46.7,7.85,900"},
                                {"heading", "30"}}));
  ASSERT_EQ(c["tracks"].size(), 1u);
  EXPECT_EQ(c["tracks"][0]["name"], "walk & talk.gpx");
  const std::string url = c["tracks"][0]["url"];
  EXPECT_EQ(url, "/tracks/0/walk%20%26%20talk.gpx");
  const auto track = http::get(serve.port(), url);
  EXPECT_EQ(track.status, 200);
  EXPECT_EQ(track.header("content-type"), "application/octet-stream");
  EXPECT_EQ(track.body, read(site.track));

  // Two requests on one connection: the connection is kept for the next.
  http::Socket s(serve.port());
  ASSERT_TRUE(s.ok());
  s.send_all("GET /app.js HTTP/1.1\r\nHost: localhost\r\n\r\n");
  EXPECT_EQ(http::read_response(s, 30).status, 200);
  s.send_all("GET /style.css HTTP/1.1\r\nHost: localhost\r\n\r\n");
  EXPECT_EQ(http::read_response(s, 30).body, "body{}");

  EXPECT_EQ(serve.stop(SIGTERM), 0);
}

TEST(ServeCli, WithoutAWebAppTheRootSaysHowToBuildItAndListsTheTracks) {
  Site site;
  auto args = base_args(site);
  args[7] = (site.dir.path() / "not-built").string();
  args.push_back(site.track.string());
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  const auto page = http::get(serve.port(), "/");
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.header("content-type"), "text/html; charset=utf-8");
  EXPECT_NE(page.body.find("scripts/web.sh"), std::string::npos) << page.body;
  EXPECT_NE(page.body.find("walk &amp; talk.gpx"), std::string::npos) << page.body;
  EXPECT_EQ(http::get(serve.port(), "/app.js").status, 404);
  EXPECT_EQ(serve.stop(SIGINT), 0);
}

TEST(ServeCli, TraversalAttemptsNeverReachAFileOutsideTheRoot) {
  Site site;
  auto args = base_args(site);
  args.push_back(site.track.string());
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  const std::string root = site.web.string();
  for (const std::string& target : std::vector<std::string>{"/../secret.txt",
                                                            "/%2e%2e/secret.txt",
                                                            "/%2E%2E/secret.txt",
                                                            "/.%2e/secret.txt",
                                                            "/sub/../../secret.txt",
                                                            "/sub/%2e%2e/%2e%2e/secret.txt",
                                                            "/..%2fsecret.txt",
                                                            "/%2e%2e%2fsecret.txt",
                                                            "//secret.txt",
                                                            "/sub//../../secret.txt",
                                                            "/..\\secret.txt",
                                                            "/%5c..%5csecret.txt",
                                                            "/sub%5c..%5c..%5csecret.txt",
                                                            "/index.html%00.png",
                                                            "/link.txt",
                                                            "/.hidden",
                                                            "/%2ehidden",
                                                            "/sub/.",
                                                            "/.",
                                                            "/..",
                                                            "/%",
                                                            "/%zz",
                                                            "/tracks/0/../../secret.txt",
                                                            "/tracks/0/%2e%2e%2f%2e%2e%2fsecret.txt",
                                                            "/tracks/..%2f..%2fsecret.txt",
                                                            std::string("/") + site.secret.string(),
                                                            std::string("/") + root + "/../secret.txt",
                                                            "http://127.0.0.1/../secret.txt",
                                                            "*",
                                                            "../secret.txt",
                                                            "/tiles/terrain/../../secret.txt"}) {
    const auto r = http::get(serve.port(), target);
    EXPECT_TRUE(r.status == 400 || r.status == 404) << target << " -> " << r.status;
    EXPECT_EQ(r.body.find("TOP SECRET"), std::string::npos) << target;
    EXPECT_EQ(r.body.find("hidden"), std::string::npos) << target;
  }
  // A NUL byte sent as it is: libmicrohttpd reads the target up to it (and may keep the
  // connection open, hence the short wait).
  const auto nul =
      http::exchange(serve.port(), std::string("GET /index.html\0/../../secret.txt HTTP/1.1\r\n\r\n", 45), 3);
  EXPECT_EQ(nul.body.find("TOP SECRET"), std::string::npos);
  EXPECT_EQ(http::get(serve.port(), "/").status, 200);  // still serving
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, UnknownPathsMethodsAndHostsAreRefused) {
  Site site;
  auto args = base_args(site);
  args.push_back(site.track.string());
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  for (const std::string target :
       {"/nope", "/nope/", "/api", "/api/", "/api/other.json", "/api/config.json/x", "/tracks", "/tracks/0",
        "/tracks/1/walk%20%26%20talk.gpx", "/tracks/0/other.gpx", "/tracks/00/walk%20%26%20talk.gpx",
        "/tracks/-1/x.gpx", "/tiles/terrain/1/0/0.png", "/tiles/imagery/1/0/0", "/tiles/other/1/0/0", "/app.js/"})
    EXPECT_EQ(http::get(serve.port(), target).status, 404) << target;
  for (const std::string method : {"POST", "PUT", "DELETE", "OPTIONS", "PATCH"}) {
    const auto r = http::exchange(serve.port(), method + " / HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n\r\n");
    EXPECT_EQ(r.status, 405) << method;
    EXPECT_EQ(r.header("allow"), "GET, HEAD") << method;
  }
  // A page whose name was pointed at 127.0.0.1 (DNS rebinding) is not answered.
  EXPECT_EQ(http::exchange(serve.port(), "GET / HTTP/1.1\r\nHost: evil.example:80\r\n\r\n").status, 403);
  EXPECT_EQ(http::exchange(serve.port(), "GET / HTTP/1.1\r\nHost: localhost:1\r\n\r\n").status, 200);
  // Garbage gets an error or a closed connection, never an answer from the site (blank lines
  // before a request are allowed: that one waits for the request, hence the short wait).
  for (const std::string garbage : {"HELLO\r\n\r\n", "GET\r\n\r\n", "\r\n\r\n\r\n", "GET / HTTP/9.9\r\n\r\n"}) {
    const auto r = http::exchange(serve.port(), garbage, 3);
    EXPECT_TRUE(r.status == 0 || r.status >= 400) << garbage << " -> " << r.status;
  }
  EXPECT_EQ(http::get(serve.port(), "/").status, 200);
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, AnOversizedRequestIsRefusedAndTheServerGoesOn) {
  Site site;
  ServeProcess serve(base_args(site));
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  for (const std::string& request :
       {"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: " + std::string(100 * 1024, 'a') + "\r\n\r\n",
        "GET /" + std::string(100 * 1024, 'a') + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"}) {
    const auto r = http::exchange(serve.port(), request, 30);
    EXPECT_FALSE(r.timed_out);
    EXPECT_TRUE(r.status == 0 || (r.status >= 400 && r.status < 500)) << r.status;
  }
  EXPECT_EQ(http::get(serve.port(), "/").status, 200);
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, ManySlowClientsDoNotStallANormalOne) {
  Site site;
  auto args = base_args(site);
  args.insert(args.end(), {"--idle-timeout", "600"});  // only the server's design can rescue the normal client
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  std::vector<http::Socket> slow;
  for (int i = 0; i < 200; ++i) {
    slow.emplace_back(serve.port());
    ASSERT_TRUE(slow.back().ok()) << i;
    slow.back().send_all("GET /app.js HT");  // half a request line, then nothing
  }
  // The bound is loose (a loaded machine); a server that waits on the slow ones would need the
  // idle timeout, ten minutes.
  const auto r = http::exchange(serve.port(), "GET /app.js HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", 20);
  EXPECT_EQ(r.status, 200);
  EXPECT_LT(r.seconds, 5.0);
  // The slow ones finishing their request are answered too.
  slow[0].send_all("TP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(http::read_response(slow[0], 20).status, 200);
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, ClientsThatLeaveMidAnswerHarmNothing) {
  Site site;
  std::string big(32u << 20, 'x');  // far more than the sockets' buffers hold
  for (std::size_t k = 0; k < big.size(); k += 4096) big[k] = static_cast<char>('a' + (k / 4096) % 26);
  write(site.web / "big.bin", big);
  ServeProcess serve(base_args(site));
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  for (int i = 0; i < 5; ++i) {
    http::Socket s(serve.port());
    s.send_all("GET /big.bin HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    const std::string start = s.receive(10, [](const std::string& in) { return in.size() > 100000; });
    EXPECT_GT(start.size(), 100000u) << i;
  }  // each closes with most of the file unsent
  // A request line cut off by the client's close.
  {
    http::Socket s(serve.port());
    s.send_all("GET /big.b");
  }
  const auto whole = http::get(serve.port(), "/big.bin");
  EXPECT_EQ(whole.status, 200);
  EXPECT_TRUE(whole.body == big) << whole.body.size();
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, BeyondTheConnectionLimitClientsAreToldSoAndServedLater) {
  Site site;
  auto args = base_args(site);
  args.insert(args.end(), {"--max-connections", "8", "--idle-timeout", "600"});
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  std::vector<http::Socket> held;
  for (int i = 0; i < 8; ++i) {
    held.emplace_back(serve.port());
    // A whole request first: its answer proves the server counts this connection.
    held.back().send_all("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    ASSERT_EQ(http::read_response(held.back(), 20).status, 200) << i;
    held.back().send_all("GET / HT");
  }
  // The holders are in (each gets its answer once it finishes its request: checked with the first).
  for (int i = 0; i < 3; ++i) {
    const auto r = http::exchange(serve.port(), "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", 20);
    EXPECT_FALSE(r.timed_out) << "a client beyond the limit is left waiting";
    EXPECT_TRUE(r.status == 503 || r.status == 0) << r.status;
    if (r.status == 503) {
      EXPECT_EQ(r.header("retry-after"), "1");
    }
  }
  held[0].send_all("TP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(http::read_response(held[0], 20).status, 200);
  held.clear();
  // Once they are gone, new clients are served again (the closes reach the server soon).
  int status = 0;
  for (int attempt = 0; attempt < 100 && status != 200; ++attempt) {
    status = http::get(serve.port(), "/").status;
    if (status != 200) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(status, 200);
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, ABadTrackFailsAtStartNamingTheFileAndPlace) {
  Site site;
  const fs::path bad = site.dir.path() / "broken.gpx";
  write(bad,
        "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\"><trk><trkseg>\n<trkpt lat=\"46.7\" lon=\"7.8\"></trkpt>\n"
        "<trkpt lat=\"46.7\" lon=\"7.8\"></wrong>\n</trkseg></trk></gpx>\n");
  auto args = base_args(site);
  args.insert(args.end(), {site.track.string(), bad.string()});
  ServeProcess serve(args);
  EXPECT_FALSE(serve.started());
  EXPECT_EQ(serve.wait_exit(), 1);
  const std::string err = serve.stderr_text();
  EXPECT_NE(err.find("error: " + bad.string() + ":4:31: malformed XML"), std::string::npos) << err;
  EXPECT_EQ(serve.first_line().find("serving"), std::string::npos);
}

TEST(ServeCli, APortInUseIsAClearError) {
  Site site;
  ServeProcess first(base_args(site));
  ASSERT_TRUE(first.started()) << first.stderr_text();
  auto args = base_args(site);
  args[1] = std::to_string(first.port());
  ServeProcess second(args);
  EXPECT_FALSE(second.started());
  EXPECT_EQ(second.wait_exit(), 1);
  EXPECT_NE(second.stderr_text().find("127.0.0.1:" + std::to_string(first.port()) +
                                      ": cannot listen (Address already in use)"),
            std::string::npos)
      << second.stderr_text();
  EXPECT_EQ(http::get(first.port(), "/").status, 200);
  EXPECT_EQ(first.stop(), 0);
}

TEST(ServeCli, TerrainTilesAreTheTerrainLayersHeightsAsTerrarium) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  Site site;
  auto args = base_args(site);
  args[3] = dem.string();
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  const json c = json::parse(http::get(serve.port(), "/api/config.json").body);
  ASSERT_TRUE(c["terrain"].is_object()) << c.dump();
  EXPECT_EQ(c["terrain"]["url"], "/tiles/terrain/{z}/{x}/{y}.png");
  EXPECT_EQ(c["terrain"]["encoding"], "terrarium");
  const int zoom = c["terrain"]["max_zoom"];
  trailray::terrain::GdalHeightSource layer(dem.string());
  EXPECT_EQ(zoom, layer.info().max_zoom);
  ASSERT_EQ(c["terrain"]["bounds"].size(), 4u);
  EXPECT_NEAR(c["terrain"]["bounds"][0].get<double>(), 7.8142, 1e-3);

  // Points inside the DEM (the flight's take-off region), their heights from `trailray elevation`.
  const std::vector<std::pair<double, double>> points{{46.7000, 7.8500}, {46.7200, 7.8300}, {46.6900, 7.9000}};
  std::string gpx = "<gpx version=\"1.1\" creator=\"t\"><trk><trkseg>\n";
  for (const auto& [lat, lon] : points) gpx += fmt::format("<trkpt lat=\"{}\" lon=\"{}\"/>\n", lat, lon);
  gpx += "</trkseg></trk></gpx>\n";
  const fs::path points_file = site.dir.path() / "points.gpx";
  write(points_file, gpx);
  const auto elevation = trailray::test::run_command(
      "TRAILRAY_CONFIG= " + trailray::test::shell_quote(TRAILRAY_BINARY) + " elevation --json --terrain " +
      trailray::test::shell_quote(dem.string()) + " " + trailray::test::shell_quote(points_file.string()));
  ASSERT_EQ(elevation.status, 0) << elevation.out;
  const json e = json::parse(elevation.out);

  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [lat, lon] = points[i];
    const auto where = trailray::geo::tile_pixel(lat, lon, zoom, 256);
    ASSERT_TRUE(where);
    const auto& id = where->tile;
    const auto r = http::get(serve.port(), fmt::format("/tiles/terrain/{}/{}/{}.png", id.zoom, id.x, id.y));
    ASSERT_EQ(r.status, 200) << trailray::geo::to_string(id);
    EXPECT_EQ(r.header("content-type"), "image/png");
    const std::vector<unsigned char> bytes(r.body.begin(), r.body.end());
    const auto served = trailray::terrain::decode_height_tile(bytes, trailray::terrain::HeightEncoding::terrarium, id);
    // Every sample the terrain layer's, to Terrarium's step (1/256 m); holes where it has none.
    const auto direct = layer.load(id, {});
    ASSERT_EQ(direct.status, trailray::terrain::TileStatus::ok);
    ASSERT_EQ(served.width, direct.tile.width);
    ASSERT_EQ(served.heights.size(), direct.tile.heights.size());
    for (std::size_t k = 0; k < served.heights.size(); ++k) {
      const float a = served.heights[k], b = direct.tile.heights[k];
      ASSERT_EQ(std::isnan(a), std::isnan(b)) << k;
      if (!std::isnan(a)) {
        ASSERT_NEAR(a, b, 1.0 / 256 + 1e-3) << k;
      }
    }
    // `elevation` samples the DEM's own grid, the tile a warped one: its height lies within the
    // tile's samples around the point (bilinear never leaves the range of its neighbours), plus
    // a metre for the two grids' interpolation.
    const double want = e["points"][i]["terrain_m"];
    float lo = 1e9f, hi = -1e9f;
    const int c0 = static_cast<int>(std::floor(where->px - 0.5)), r0 = static_cast<int>(std::floor(where->py - 0.5));
    for (int row = std::max(0, r0 - 1); row <= std::min(255, r0 + 2); ++row)
      for (int col = std::max(0, c0 - 1); col <= std::min(255, c0 + 2); ++col) {
        lo = std::min(lo, served.at(static_cast<std::uint32_t>(col), static_cast<std::uint32_t>(row)));
        hi = std::max(hi, served.at(static_cast<std::uint32_t>(col), static_cast<std::uint32_t>(row)));
      }
    EXPECT_GE(want, lo - 1.0) << lat << "," << lon;
    EXPECT_LE(want, hi + 1.0) << lat << "," << lon;
    EXPECT_GT(want, 500.0);
  }
  // Outside the DEM, and above its finest level: nothing.
  EXPECT_EQ(http::get(serve.port(), "/tiles/terrain/10/0/0.png").status, 404);
  const auto top = trailray::geo::tile_containing(46.70, 7.85, zoom + 1);
  EXPECT_EQ(http::get(serve.port(), fmt::format("/tiles/terrain/{}/{}/{}.png", top->zoom, top->x, top->y)).status, 404);
  EXPECT_EQ(http::get(serve.port(), "/tiles/terrain/1/2/0.png").status, 404);  // x beyond the pyramid
  EXPECT_EQ(http::get(serve.port(), "/tiles/terrain/1/0/0").status, 404);      // no .png
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, ImageryTilesGoOutAsStored) {
  Site site;
  const fs::path folder = site.dir.path() / "imagery";
  trailray::terrain::DecodedImage image;
  image.width = image.height = 256;
  image.channels = 3;
  image.samples8.assign(256 * 256 * 3, 0);
  for (std::size_t k = 0; k < image.samples8.size(); ++k) image.samples8[k] = static_cast<std::uint8_t>(k * 7);
  const auto jpeg = trailray::terrain::encode_jpeg(image, 80);
  write(folder / "3" / "4" / "2.jpg", std::string(jpeg.begin(), jpeg.end()));
  auto args = base_args(site);
  args[5] = folder.string();
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  const json c = json::parse(http::get(serve.port(), "/api/config.json").body);
  ASSERT_TRUE(c["imagery"].is_object()) << c.dump();
  EXPECT_EQ(c["imagery"]["url"], "/tiles/imagery/{z}/{x}/{y}");
  const auto r = http::get(serve.port(), "/tiles/imagery/3/4/2");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.header("content-type"), "image/jpeg");
  EXPECT_EQ(r.body, std::string(jpeg.begin(), jpeg.end()));
  EXPECT_EQ(r.header("access-control-allow-origin"), "*");
  EXPECT_EQ(http::get(serve.port(), "/tiles/imagery/3/4/3").status, 404);
  // Tiles (answered by a worker) keep the connection for the next request, as a page loading
  // hundreds of them needs.
  http::Socket s(serve.port());
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(s.send_all("GET /tiles/imagery/3/4/2 HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")) << i;
    const auto again = http::read_response(s, 30);
    EXPECT_EQ(again.status, 200) << i;
    EXPECT_EQ(again.body.size(), jpeg.size()) << i;
    EXPECT_NE(again.header("connection"), "close") << i;
  }
  EXPECT_EQ(serve.stop(), 0);
}

TEST(ServeCli, BadOptionsAreUsageErrors) {
  Site site;
  for (const std::vector<std::string>& extra : {std::vector<std::string>{"--color-by", "nonsense"},
                                                {"--port", "70000"},
                                                {"--camera", "x"},
                                                {"--bind", "not-an-address"},
                                                {"-"}}) {
    auto args = base_args(site);
    args.insert(args.end(), extra.begin(), extra.end());
    ServeProcess serve(args);
    EXPECT_FALSE(serve.started()) << extra[0];
    const auto status = serve.wait_exit();
    EXPECT_TRUE(status == 1 || status == 2) << extra[0] << ": " << status.value_or(-9) << serve.stderr_text();
  }
}

TEST(ServeCli, ASlowTileSourceHoldsUpNoOtherRequestAndStopsOnSignal) {
  trailray::test::http::LocalTileServer upstream;  // its /slow/ tiles never come
  Site site;
  auto args = base_args(site);
  args[3] = upstream.url("/slow/{z}/{x}/{y}.png");
  ServeProcess serve(args);
  ASSERT_TRUE(serve.started()) << serve.stderr_text();
  // More tiles asked for than the server has workers: all of them wait on the upstream.
  std::vector<http::Socket> waiting;
  for (std::uint32_t x = 0; x < 32; ++x) {
    waiting.emplace_back(serve.port());
    waiting.back().send_all(fmt::format("GET /tiles/terrain/5/{}/11.png HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", x));
  }
  for (int i = 0; i < 200 && upstream.request_count("/slow/") == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_GT(upstream.request_count("/slow/"), 0);
  const auto page = http::get(serve.port(), "/app.js");
  EXPECT_EQ(page.status, 200);
  EXPECT_LT(page.seconds, 5.0);
  EXPECT_EQ(http::get(serve.port(), "/api/config.json").status, 200);
  // The signal cancels the waiting tiles (503 or a closed connection), then the server ends.
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(serve.stop(SIGTERM, 60), 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  for (auto& s : waiting) {
    const auto r = http::read_response(s, 5);
    EXPECT_TRUE(r.status == 0 || r.status == 503) << r.status;
  }
}
