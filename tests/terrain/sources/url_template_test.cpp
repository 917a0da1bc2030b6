#include "terrain/sources/url_template.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace {

TileId tile(int z, std::uint32_t x, std::uint32_t y) { return TileId{z, x, y}; }

std::string url(const UrlTemplate& t, const TileId& id) {
  ExpandedText expanded = t.url_for(id);
  EXPECT_EQ(expanded.error, "");
  return expanded.text;
}

// The SourceError message for a template, or "" when it parses.
std::string rejection(std::string_view text, std::string_view subdomains = "a,b,c") {
  try {
    UrlTemplate parsed(text, subdomains);
  } catch (const SourceError& e) {
    return e.what();
  }
  return {};
}

TEST(UrlTemplate, FillsZoomColumnAndRow) {
  const UrlTemplate t("https://tiles.example.org/terrain/{z}/{x}/{y}.png");
  EXPECT_EQ(url(t, tile(12, 2137, 1445)), "https://tiles.example.org/terrain/12/2137/1445.png");
  EXPECT_EQ(url(t, tile(0, 0, 0)), "https://tiles.example.org/terrain/0/0/0.png");
  EXPECT_EQ(t.display(), "https://tiles.example.org/terrain/{z}/{x}/{y}.png");
}

TEST(UrlTemplate, TmsRowCountsFromTheSouth) {
  const UrlTemplate t("http://h/{z}/{x}/{-y}.jpg");
  EXPECT_EQ(url(t, tile(3, 5, 1)), "http://h/3/5/6.jpg");  // 2^3 - 1 - 1
  EXPECT_EQ(url(t, tile(7, 68, 45)), "http://h/7/68/82.jpg");
  EXPECT_EQ(url(t, tile(0, 0, 0)), "http://h/0/0/0.jpg");
}

TEST(UrlTemplate, SubdomainIsPickedFromColumnAndRow) {
  const UrlTemplate t("https://{s}.tile.example.org/{z}/{x}/{y}.png");
  EXPECT_EQ(url(t, tile(5, 0, 0)), "https://a.tile.example.org/5/0/0.png");
  EXPECT_EQ(url(t, tile(5, 1, 0)), "https://b.tile.example.org/5/1/0.png");
  EXPECT_EQ(url(t, tile(5, 1, 1)), "https://c.tile.example.org/5/1/1.png");
  EXPECT_EQ(url(t, tile(5, 2, 1)), "https://a.tile.example.org/5/2/1.png");
  EXPECT_EQ(url(t, tile(5, 2, 1)), url(t, tile(5, 2, 1)));  // always the same host for a tile

  const UrlTemplate custom("https://{s}.example.org/{z}/{x}/{y}", " t0, t1 ");
  EXPECT_EQ(custom.subdomains(), (std::vector<std::string>{"t0", "t1"}));
  EXPECT_EQ(url(custom, tile(5, 3, 0)), "https://t1.example.org/5/3/0");
  EXPECT_EQ(url(custom, tile(5, 3, 1)), "https://t0.example.org/5/3/1");
}

TEST(UrlTemplate, LargeCoordinatesDoNotOverflowTheSubdomainChoice) {
  const UrlTemplate t("https://{s}.example.org/{z}/{x}/{y}");
  const std::uint32_t last = (1u << 30) - 1;
  // (x + y) computed in 64 bits: 2 * (2^30 - 1) mod 3 == 0.
  EXPECT_EQ(url(t, tile(30, last, last)),
            "https://a.example.org/30/" + std::to_string(last) + "/" + std::to_string(last));
}

TEST(UrlTemplate, RejectsTemplatesMissingAPlaceholder) {
  EXPECT_NE(rejection("https://h/{x}/{y}.png").find("no {z}"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{y}.png").find("no {x}"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x}.png").find("no {y} or {-y}"), std::string::npos);
  EXPECT_EQ(rejection("https://h/{z}/{x}/{-y}.png"), "");
}

TEST(UrlTemplate, RejectsUnknownAndMalformedPlaceholders) {
  const std::string unknown = rejection("https://h/{z}/{x}/{y}/{quadkey}.png");
  EXPECT_NE(unknown.find("unknown placeholder {quadkey} at column 23"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("https://h/{z}/{x}/{y}/{quadkey}.png"), std::string::npos) << unknown;  // names the source
  EXPECT_NE(rejection("https://h/{z}/{x}/{y.png").find("unclosed {"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x/{y}.png").find("unclosed {"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x}/{y}}.png").find("unmatched }"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x}/{y}.png?k=${KEY").find("unclosed ${"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x}/{y}.png?k=${1KEY}").find("bad variable name"), std::string::npos);
  EXPECT_NE(rejection("https://h/{z}/{x}/{y}.png?k=${}").find("bad variable name"), std::string::npos);
}

TEST(UrlTemplate, RejectsOtherSchemesAndAnEmptySubdomainList) {
  EXPECT_NE(rejection("ftp://h/{z}/{x}/{y}.png").find("not an http:// or https:// URL"), std::string::npos);
  EXPECT_NE(rejection("/tiles/{z}/{x}/{y}.png").find("not an http"), std::string::npos);
  EXPECT_EQ(rejection("HTTPS://h/{z}/{x}/{y}.png"), "");
  EXPECT_NE(rejection("https://{s}.h/{z}/{x}/{y}.png", " , ").find("subdomain list is empty"), std::string::npos);
  EXPECT_EQ(rejection("https://h/{z}/{x}/{y}.png", ""), "");  // no {s}: no list needed
}

TEST(UrlTemplate, EnvironmentIsReadWhenTheUrlIsBuilt) {
  ::unsetenv("TRAILRAY_URL_TEST_KEY");
  const UrlTemplate t("https://h/{z}/{x}/{y}.webp?key=${TRAILRAY_URL_TEST_KEY}&v=${TRAILRAY_URL_TEST_KEY}");
  EXPECT_EQ(t.environment_variables(), (std::vector<std::string>{"TRAILRAY_URL_TEST_KEY"}));

  ExpandedText unset = t.url_for(tile(1, 0, 1));
  EXPECT_EQ(unset.text, "");
  EXPECT_EQ(unset.error, t.display() + " 1/0/1: environment variable TRAILRAY_URL_TEST_KEY is not set");

  ::setenv("TRAILRAY_URL_TEST_KEY", "k-first", 1);
  ExpandedText first = t.url_for(tile(1, 0, 1));
  EXPECT_EQ(first.text, "https://h/1/0/1.webp?key=k-first&v=k-first");
  EXPECT_EQ(first.secrets, (std::vector<std::string>{"k-first", "k-first"}));

  ::setenv("TRAILRAY_URL_TEST_KEY", "k-second", 1);  // a new key is picked up without re-parsing
  EXPECT_EQ(url(t, tile(1, 0, 1)), "https://h/1/0/1.webp?key=k-second&v=k-second");
  EXPECT_EQ(t.display(), "https://h/{z}/{x}/{y}.webp?key=${TRAILRAY_URL_TEST_KEY}&v=${TRAILRAY_URL_TEST_KEY}");
  EXPECT_EQ(t.display().find("k-second"), std::string::npos);
  ::unsetenv("TRAILRAY_URL_TEST_KEY");
}

TEST(UrlTemplate, InvalidTileIsAnErrorNotAUrl) {
  const UrlTemplate t("https://h/{z}/{x}/{-y}.png");
  ExpandedText out = t.url_for(tile(2, 4, 0));
  EXPECT_EQ(out.text, "");
  EXPECT_EQ(out.error, "https://h/{z}/{x}/{-y}.png 2/4/0: not a valid tile id");
}

TEST(ExpandEnvironment, ReplacesReferencesAndKeepsOtherDollars) {
  ::setenv("TRAILRAY_HEADER_TEST_TOKEN", "tok-123", 1);
  ExpandedText out = expand_environment("Bearer ${TRAILRAY_HEADER_TEST_TOKEN}; $5 $HOME");
  EXPECT_EQ(out.error, "");
  EXPECT_EQ(out.text, "Bearer tok-123; $5 $HOME");
  EXPECT_EQ(out.secrets, (std::vector<std::string>{"tok-123"}));
  EXPECT_EQ(expand_environment("plain").text, "plain");
  ::unsetenv("TRAILRAY_HEADER_TEST_TOKEN");
  EXPECT_EQ(expand_environment("Bearer ${TRAILRAY_HEADER_TEST_TOKEN}").error,
            "environment variable TRAILRAY_HEADER_TEST_TOKEN is not set");
  EXPECT_NE(expand_environment("${oops").error, "");
}

TEST(RedactSecrets, ReplacesEveryOccurrence) {
  EXPECT_EQ(redact_secrets("GET /t?key=abc&k2=abc failed at abcd", {"abc"}), "GET /t?key=***&k2=*** failed at ***d");
  EXPECT_EQ(redact_secrets("nothing here", {"abc", ""}), "nothing here");
  // A secret that contains the mask itself is still removed, and the loop ends.
  EXPECT_EQ(redact_secrets("x***y", {"***"}), "x***y");
  EXPECT_EQ(redact_secrets("aaaa", {"aa"}), "******");
}

}  // namespace
}  // namespace trailray::terrain
