// The pieces of `trailray serve` that decide what a request names: the strict reading of the
// target, the web root's containment, tile ids in paths, loopback hosts, content types, the
// configuration's options.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <fstream>

#include "app/serve/request_path.hpp"
#include "app/serve/serve_config.hpp"
#include "app/serve/serve_site.hpp"
#include "app/serve/tile_answers.hpp"
#include "app/serve/web_root.hpp"
#include "terrain/tile_fixtures.hpp"

using namespace trailray::app::serve;
namespace fs = std::filesystem;

TEST(ServeRequestPath, DecodesSegmentsAndKeepsTheTrailingSlash) {
  auto p = parse_request_target("/tracks/0/walk%20%26%20talk.gpx?x=1#frag");
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.path.segments, (std::vector<std::string>{"tracks", "0", "walk & talk.gpx"}));
  EXPECT_FALSE(p.path.trailing_slash);
  p = parse_request_target("/");
  ASSERT_TRUE(p.ok());
  EXPECT_TRUE(p.path.segments.empty());
  EXPECT_FALSE(p.path.trailing_slash);
  p = parse_request_target("/sub/");
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.path.segments, std::vector<std::string>{"sub"});
  EXPECT_TRUE(p.path.trailing_slash);
  p = parse_request_target("/a..b/...");  // dots inside names are names
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.path.segments, (std::vector<std::string>{"a..b", "..."}));
}

TEST(ServeRequestPath, RefusesEverySpellingOfAnotherPlace) {
  for (const char* target :
       {"",          "*",       "a/b",    "http://host/a", "/..",   "/../x", "/a/../b", "/.",     "/a/./b", "/%2e%2e/x",
        "/%2E%2e/x", "/.%2e/x", "/%2e/x", "//x",           "/a//b", "/a\\b", "/%5c",    "/a%2fb", "/a%2Fb", "/%00",
        "/a%00.png", "/%",      "/%4",    "/%zz",          "/%g0",  "/a\tb", "/a%0ab",  "/a%7f"})
    EXPECT_FALSE(parse_request_target(target).ok()) << target;
  // A query may hold anything: it is not read.
  EXPECT_TRUE(parse_request_target("/a?../../%00").ok());
}

TEST(ServeRequestPath, NumbersHaveOneSpelling) {
  EXPECT_EQ(parse_segment_number("0"), 0u);
  EXPECT_EQ(parse_segment_number("17"), 17u);
  EXPECT_EQ(parse_segment_number("4294967295"), 4294967295u);
  for (const char* text : {"", "01", "00", "+1", "-1", " 1", "1 ", "1e3", "0x1", "4294967296", "99999999999", "1.0"})
    EXPECT_FALSE(parse_segment_number(text)) << text;
}

TEST(ServeWebRoot, FindsFilesInsideAndNothingOutside) {
  trailray::test::TempDir dir;
  const fs::path web = dir.path() / "web";
  fs::create_directories(web / "sub");
  std::ofstream(web / "index.html") << "i";
  std::ofstream(web / "sub" / "index.html") << "s";
  std::ofstream(web / "app.js") << "a";
  std::ofstream(web / ".env") << "e";
  std::ofstream(dir.path() / "secret") << "x";
  fs::create_directories(dir.path() / "web-other");
  std::ofstream(dir.path() / "web-other" / "f") << "x";
  fs::create_symlink(dir.path() / "secret", web / "out");
  fs::create_symlink(web / "app.js", web / "in");
  const WebRoot root(web);
  EXPECT_TRUE(root.has_index());
  auto find = [&](const std::string& target) { return root.resolve(parse_request_target(target).path); };
  EXPECT_EQ(find("/"), fs::canonical(web / "index.html"));
  EXPECT_EQ(find("/sub"), fs::canonical(web / "sub" / "index.html"));
  EXPECT_EQ(find("/sub/"), fs::canonical(web / "sub" / "index.html"));
  EXPECT_EQ(find("/app.js"), fs::canonical(web / "app.js"));
  EXPECT_EQ(find("/in"), fs::canonical(web / "app.js"));  // a link that stays inside
  EXPECT_FALSE(find("/app.js/"));
  EXPECT_FALSE(find("/out"));  // a link out of the root
  EXPECT_FALSE(find("/.env"));
  EXPECT_FALSE(find("/missing"));
  // A sibling whose name starts like the root's is not inside it.
  RequestPath climb;
  climb.segments = {"..", "web-other", "f"};
  EXPECT_FALSE(root.resolve(climb));
  EXPECT_FALSE(WebRoot(dir.path() / "nowhere").has_index());
}

TEST(ServeWebRoot, ContentTypes) {
  EXPECT_EQ(content_type_for("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type_for("app.JS"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type_for("app.wasm"), "application/wasm");
  EXPECT_EQ(content_type_for("s.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type_for("i.png"), "image/png");
  EXPECT_EQ(content_type_for("c.json"), "application/json");
  EXPECT_EQ(content_type_for("i.svg"), "image/svg+xml");
  EXPECT_EQ(content_type_for("noext"), "application/octet-stream");
}

TEST(ServeTiles, TileIdsFromPaths) {
  const std::vector<std::string> s{"tiles", "terrain", "12", "2137", "1445.png"};
  const auto id = parse_tile_segments(s, 2, ".png", 14);
  ASSERT_TRUE(id);
  EXPECT_EQ(id->zoom, 12);
  EXPECT_EQ(id->x, 2137u);
  EXPECT_EQ(id->y, 1445u);
  EXPECT_FALSE(parse_tile_segments(s, 2, ".png", 11));  // above the finest level served
  EXPECT_FALSE(parse_tile_segments(s, 2, "", 14));      // "1445.png" is no number
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"t", "k", "1", "2", "0.png"},  // x beyond 2^z - 1
                                             {"t", "k", "01", "0", "0.png"},
                                             {"t", "k", "+1", "0", "0.png"},
                                             {"t", "k", "1", "0", ".png"},
                                             {"t", "k", "1", "-0", "0.png"},
                                             {"t", "k", "99999999999", "0", "0.png"},
                                             {"t", "k", "1", "0"},
                                             {"t", "k", "1", "0", "0", "0.png"}})
    EXPECT_FALSE(parse_tile_segments(bad, 2, ".png", 30)) << bad[2] << "/" << bad[3];
}

TEST(ServeSite, LoopbackHosts) {
  for (const char* host :
       {"127.0.0.1", "127.0.0.1:8123", "localhost", "LOCALHOST:80", "[::1]:8123", "[::1]", "127.1.2.3"})
    EXPECT_TRUE(is_loopback_host(host)) << host;
  for (const char* host : {"evil.example", "evil.example:8123", "127.0.0.1.evil.example", "localhost.evil", "[::2]",
                           "10.0.0.1", "[::1", "0.0.0.0"})
    EXPECT_FALSE(is_loopback_host(host)) << host;
  EXPECT_EQ(track_url(3, "a b/#?.igc"), "/tracks/3/a%20b%2F%23%3F.igc");
}

TEST(ServeConfig, GivenOptionsAsTheyWereGiven) {
  CLI::App app;
  std::string color_by;
  std::vector<std::string> colors;
  bool no_ssao = false;
  double width = 0;
  std::string untouched;
  const std::size_t before = app.get_options().size();
  app.add_option("--color-by", color_by);
  app.add_option("--color", colors);
  app.add_flag("--no-ssao", no_ssao);
  app.add_option("--width", width);
  app.add_option("--untouched", untouched);
  const auto options = options_added_since(app, before);
  EXPECT_EQ(options.size(), 5u);
  const char* argv[] = {"x",       "--color-by", "vspeed",    "--color", "#ff00ff",
                        "--color", "red",        "--no-ssao", "--width", "5.50"};
  app.parse(10, const_cast<char**>(argv));
  EXPECT_EQ(
      given_options(options),
      nlohmann::json({{"color-by", "vspeed"}, {"color", {"#ff00ff", "red"}}, {"no-ssao", true}, {"width", "5.50"}}));
}
