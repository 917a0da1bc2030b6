// The viewer's script language: what each line becomes, and errors that name FILE:LINE.
#include "ui/view_script.hpp"

#include <gtest/gtest.h>

#include <string>

namespace trailray::ui {
namespace {

using Kind = ScriptCommand::Kind;

TEST(ViewScript, EachLineIsACommandWithItsNumbers) {
  const ViewScript s = parse_view_script(
      "# a test\n\norbit 40 -12.5\r\n  zoom -2\nselect 1\nhover 100 80\nprint-hover\nplay 5\nwait 3\n"
      "screenshot dir/a.png",
      "s.txt");
  ASSERT_EQ(s.commands.size(), 8u);
  EXPECT_EQ(s.commands[0].kind, Kind::orbit);
  EXPECT_EQ(s.commands[0].x, 40.0);
  EXPECT_EQ(s.commands[0].y, -12.5);
  EXPECT_EQ(s.commands[0].line, 3);
  EXPECT_EQ(s.commands[1].kind, Kind::zoom);
  EXPECT_EQ(s.commands[1].x, -2.0);
  EXPECT_EQ(s.commands[2].kind, Kind::select);
  EXPECT_EQ(s.commands[3].kind, Kind::hover);
  EXPECT_EQ(s.commands[3].y, 80.0);
  EXPECT_EQ(s.commands[4].kind, Kind::print_hover);
  EXPECT_EQ(s.commands[5].kind, Kind::play);
  EXPECT_EQ(s.commands[6].kind, Kind::wait);
  EXPECT_EQ(s.commands[7].kind, Kind::screenshot);
  EXPECT_EQ(s.commands[7].path, "dir/a.png");
  EXPECT_EQ(s.commands[7].line, 10);
}

void expect_error(const std::string& text, const std::string& where, const std::string& what) {
  try {
    parse_view_script(text, "view.txt");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const ScriptError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(where, 0), 0u) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
  }
}

TEST(ViewScript, ErrorsNameTheFileAndTheLine) {
  expect_error("wait 1\nfly 3\n", "view.txt:2:", "unknown command 'fly'");
  expect_error("\n\norbit left 3\n", "view.txt:3:", "'left' is not a number");
  expect_error("orbit 3\n", "view.txt:1:", "orbit DX DY");
  expect_error("wait -1\n", "view.txt:1:", "negative");
  expect_error("screenshot\n", "view.txt:1:", "screenshot PATH");
  expect_error("zoom 1e999\n", "view.txt:1:", "not a number");
}

TEST(ViewScript, WindowPicturesAndPanelsHaveTheirCommands) {
  const ViewScript s =
      parse_view_script("window-screenshot w.png\nhide-panels\nspeed 100\nprint-marker\nprint-camera\n", "s.txt");
  ASSERT_EQ(s.commands.size(), 5u);
  EXPECT_EQ(s.commands[0].kind, Kind::window_screenshot);
  EXPECT_EQ(s.commands[0].path, "w.png");
  EXPECT_EQ(s.commands[1].kind, Kind::hide_panels);
  EXPECT_EQ(s.commands[2].kind, Kind::speed);
  EXPECT_EQ(s.commands[2].x, 100.0);
  EXPECT_EQ(s.commands[3].kind, Kind::print_marker);
  EXPECT_EQ(s.commands[4].kind, Kind::print_camera);
  expect_error("hide-panels now\n", "view.txt:1:", "hide-panels");
}

TEST(ViewScript, FilmCommandsTakeAPathAndSecondsOrTheirSettings) {
  const ViewScript s = parse_view_script(
      "film-size 320 180\nfilm-fps 12\nfilm-camera orbit\nstart-film out/a.mp4 2.5\nwait 2\ncancel-film\n"
      "record-film b.webm 1\n",
      "s.txt");
  ASSERT_EQ(s.commands.size(), 7u);
  EXPECT_EQ(s.commands[0].kind, Kind::film_size);
  EXPECT_EQ(s.commands[0].x, 320.0);
  EXPECT_EQ(s.commands[0].y, 180.0);
  EXPECT_EQ(s.commands[1].kind, Kind::film_fps);
  EXPECT_EQ(s.commands[1].x, 12.0);
  EXPECT_EQ(s.commands[2].kind, Kind::film_camera);
  EXPECT_EQ(s.commands[2].path, "orbit");
  EXPECT_EQ(s.commands[3].kind, Kind::start_film);
  EXPECT_EQ(s.commands[3].path, "out/a.mp4");
  EXPECT_EQ(s.commands[3].x, 2.5);
  EXPECT_EQ(s.commands[5].kind, Kind::cancel_film);
  EXPECT_EQ(s.commands[6].kind, Kind::record_film);
  EXPECT_EQ(s.commands[6].path, "b.webm");
  EXPECT_EQ(s.commands[6].x, 1.0);
  expect_error("record-film a.mp4\n", "view.txt:1:", "record-film PATH SECONDS");
  expect_error("wait 1\nrecord-film a.mp4 long\n", "view.txt:2:", "'long' is not a number");
  expect_error("start-film a.mp4 -3\n", "view.txt:1:", "negative");
  expect_error("film-camera sideways\n", "view.txt:1:", "'sideways' is not a film camera");
  expect_error("film-size 320\n", "view.txt:1:", "film-size WIDTH HEIGHT");
  expect_error("cancel-film now\n", "view.txt:1:", "cancel-film");
}

TEST(ViewScript, AMissingFileIsNamed) {
  try {
    load_view_script("/nonexistent/script.txt");
    ADD_FAILURE();
  } catch (const ScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/script.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace trailray::ui
