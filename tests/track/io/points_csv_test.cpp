// The points CSV of --labels: columns found by their header in any order, separators, quoting,
// and errors that name the file and the line.

#include "track/io/points_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"

namespace trailray::track {
namespace {

TEST(PointsCsv, ColumnsInAnyOrderAndTheirOtherNames) {
  const ReadResult r = read_points_csv("Elevation,Longitude,Name,latitude\n2864,13.8369,Triglav,46.3783\n", "p.csv");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  const Waypoint& w = r.file.waypoints[0];
  EXPECT_EQ(w.name, "Triglav");
  EXPECT_DOUBLE_EQ(w.point.lat, 46.3783);
  EXPECT_DOUBLE_EQ(w.point.lon, 13.8369);
  EXPECT_DOUBLE_EQ(w.point.ele, 2864.0);
}

TEST(PointsCsv, SemicolonsTabsQuotesCommentsAndEmptyElevation) {
  const ReadResult semi = read_points_csv(
      "# huts\nname;lat;lon;alt;desc\n\"Dom; Planika\";46.37;13.83;;\"a "
      "\"\"hut\"\"\"\r\n\nKredarica;46.379;13.849;2515;\n",
      "p.csv");
  ASSERT_TRUE(semi.ok()) << semi.error->to_string();
  ASSERT_EQ(semi.file.waypoints.size(), 2u);
  EXPECT_EQ(semi.file.waypoints[0].name, "Dom; Planika");
  EXPECT_EQ(semi.file.waypoints[0].description, "a \"hut\"");
  EXPECT_TRUE(std::isnan(semi.file.waypoints[0].point.ele));
  EXPECT_DOUBLE_EQ(semi.file.waypoints[1].point.ele, 2515.0);

  const ReadResult tabs = read_points_csv("lat\tlon\tname\n1.5\t2.5\tA B\n", "p.tsv");
  ASSERT_TRUE(tabs.ok());
  ASSERT_EQ(tabs.file.waypoints.size(), 1u);
  EXPECT_EQ(tabs.file.waypoints[0].name, "A B");
  EXPECT_DOUBLE_EQ(tabs.file.waypoints[0].point.lon, 2.5);
}

TEST(PointsCsv, ErrorsNameTheFileAndLine) {
  const ReadResult bad_number = read_points_csv("name,lat,lon\nA,46.0,13.0\nB,north,13.0\n", "huts.csv");
  ASSERT_FALSE(bad_number.ok());
  EXPECT_EQ(bad_number.error->to_string().rfind("huts.csv:3: ", 0), 0u) << bad_number.error->to_string();
  EXPECT_TRUE(bad_number.file.waypoints.empty());

  const ReadResult out_of_range = read_points_csv("name,lat,lon\n\nA,95.0,13.0\n", "huts.csv");
  ASSERT_FALSE(out_of_range.ok());
  EXPECT_EQ(out_of_range.error->position.line, 3);

  const ReadResult short_row = read_points_csv("name,lat,lon\nA,46.0\n", "huts.csv");
  ASSERT_FALSE(short_row.ok());
  EXPECT_EQ(short_row.error->position.line, 2);

  const ReadResult bad_ele = read_points_csv("name,lat,lon,ele\nA,46,13,high\n", "huts.csv");
  ASSERT_FALSE(bad_ele.ok());
  EXPECT_NE(bad_ele.error->message.find("high"), std::string::npos);

  const ReadResult no_lat = read_points_csv("name,lon\nA,13\n", "huts.csv");
  ASSERT_FALSE(no_lat.ok());
  EXPECT_EQ(no_lat.error->position.line, 1);
  EXPECT_NE(no_lat.error->message.find("lat"), std::string::npos);

  EXPECT_FALSE(read_points_csv("", "empty.csv").ok());
  EXPECT_FALSE(read_points_csv("lat,lon,lat\n1,2,3\n", "twice.csv").ok());
}

TEST(PointsCsv, LoadPicksCsvByNameAndOtherFilesByContent) {
  const test::TempFile csv("peaks.CSV", "\xEF\xBB\xBFname,lat,lon\nTriglav,46.3783,13.8369\n");
  const ReadResult r = load_points_file(csv.str());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "Triglav");

  const test::TempFile gpx("peaks.gpx",
                           "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\"><wpt lat=\"46.1\" lon=\"13.2\">"
                           "<ele>1000</ele><name>Peak</name></wpt></gpx>");
  const ReadResult g = load_points_file(gpx.str());
  ASSERT_TRUE(g.ok()) << g.error->to_string();
  ASSERT_EQ(g.file.waypoints.size(), 1u);
  EXPECT_EQ(g.file.waypoints[0].name, "Peak");

  const ReadResult missing = load_points_file("/nonexistent/peaks.csv");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error->to_string().find("/nonexistent/peaks.csv"), std::string::npos);
}

}  // namespace
}  // namespace trailray::track
