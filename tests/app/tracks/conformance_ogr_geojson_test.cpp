// Conformance with GDAL's GeoJSON driver (ogrinfo, Debian gdal-bin), read in the same test run:
// for every file in shared/data/geojson, the positions GDAL reads are the positions trailray
// reads (as `trailray convert --format csv` writes them), the same number, the same values.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "test_support.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;

namespace {

using Position = std::array<double, 3>;  // lon, lat, ele (NaN when absent)

// Positions of the line and point geometries ogrinfo prints as WKT ("  LINESTRING Z (x y z,...)").
std::vector<Position> ogr_positions(const std::string& text) {
  std::vector<Position> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("  ")) continue;
    const std::string body = line.substr(2);
    if (!(body.starts_with("POINT") || body.starts_with("LINESTRING") || body.starts_with("MULTILINESTRING") ||
          body.starts_with("MULTIPOINT") || body.starts_with("GEOMETRYCOLLECTION")))
      continue;
    const bool z = body.find(" Z ") != std::string::npos;
    std::vector<double> numbers;
    const char* p = body.c_str();
    while (*p) {
      if (std::isdigit(static_cast<unsigned char>(*p)) || *p == '-' || *p == '.') {
        char* end = nullptr;
        numbers.push_back(std::strtod(p, &end));
        p = end;
      } else {
        ++p;
      }
    }
    const std::size_t dims = z ? 3 : 2;
    for (std::size_t i = 0; i + dims <= numbers.size(); i += dims)
      out.push_back({numbers[i], numbers[i + 1], z ? numbers[i + 2] : NAN});
  }
  return out;
}

// RFC 4180 fields of a CSV text (quoted fields may hold commas and line breaks).
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        field += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field), field.clear();
    } else if (c == '\n') {
      rows.back().push_back(field), field.clear();
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

std::vector<Position> trailray_positions(const std::string& path) {
  auto r = run_command(shell_quote(TRAILRAY_BINARY) + " convert " + shell_quote(path) + " --format csv -o -");
  EXPECT_EQ(r.status, 0) << path;
  std::vector<Position> out;
  const auto rows = csv_rows(r.out);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& f = rows[i];
    EXPECT_EQ(f.size(), 13u);
    if (f.size() < 7) continue;
    out.push_back({std::stod(f[5]), std::stod(f[4]), f[6].empty() ? NAN : std::stod(f[6])});
  }
  return out;
}

bool before(const Position& a, const Position& b) {
  for (int i = 0; i < 3; ++i) {
    const double x = std::isnan(a[i]) ? -1e300 : a[i], y = std::isnan(b[i]) ? -1e300 : b[i];
    if (x != y) return x < y;
  }
  return false;
}

}  // namespace

TEST(ConformanceOgr, GeoJsonPositionsMatchGdalOnEveryFile) {
  TRAILRAY_REQUIRE_DATA(dir, "geojson");
  int files = 0;
  std::size_t positions = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string path = e.path().string();
    auto ogr = run_command("ogrinfo -ro -al -q -fields=NO " + shell_quote(path) + " 2>&1");
    ASSERT_EQ(ogr.status, 0) << "ogrinfo (gdal-bin, scripts/setup.sh) failed on " << path << ": " << ogr.out;
    std::vector<Position> theirs = ogr_positions(ogr.out), ours = trailray_positions(path);
    // Same set of positions; the order differs (trailray writes tracks before waypoints).
    std::sort(theirs.begin(), theirs.end(), before);
    std::sort(ours.begin(), ours.end(), before);
    ASSERT_EQ(ours.size(), theirs.size()) << path;
    for (std::size_t i = 0; i < ours.size(); ++i) {
      // ogrinfo prints 15 significant digits.
      EXPECT_NEAR(ours[i][0], theirs[i][0], 1e-9) << path << " #" << i;
      EXPECT_NEAR(ours[i][1], theirs[i][1], 1e-9) << path << " #" << i;
      EXPECT_EQ(std::isnan(ours[i][2]), std::isnan(theirs[i][2])) << path << " #" << i;
      if (!std::isnan(ours[i][2])) {
        EXPECT_NEAR(ours[i][2], theirs[i][2], 1e-9) << path << " #" << i;
      }
    }
    positions += ours.size();
    ++files;
  }
  EXPECT_EQ(files, 4);
  EXPECT_EQ(positions, 1118u + 1242u + 46u + 26u + 2u + 46u);
}
