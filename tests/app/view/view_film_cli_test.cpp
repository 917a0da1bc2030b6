// The viewer's "record film" through `trailray view --script` under Xvfb: the film it records is
// `trailray video`'s with the same options (byte for byte: both run app::FilmRecorder; WebM,
// whose encoding is deterministic), an MP4 has the codec, size and frame count asked for, the
// window shows the film's progress while it records and Cancel leaves no file, an existing film
// is not overwritten. Small films (320x180) keep each test to seconds on llvmpipe.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/track_cli_support.hpp"
#include "app/xvfb_command.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
// What both the viewer and `trailray video` are given (with RenderEnv's --imagery none): no terrain,
// no SSAO, one red track.
const std::string kStyle = " --terrain none --no-ssao --no-atmosphere --time 2024-06-18T10:00:00Z --color '#ff0000'";

struct FilmEnv : RenderEnv {
  std::string view() const {
    std::string p = prefix();
    p.replace(p.find(" render "), 8, " view ");
    return xvfb_command_prefix(file("Xauthority")) + p;
  }
  std::string video() const {
    std::string p = prefix();
    p.replace(p.find(" render "), 8, " video ");
    return p;
  }
  std::string script(const std::string& text) const {
    const std::string path = file("script.txt");
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // A hike east, 1.5 km in 10 minutes.
  std::string hike() const {
    return write_gpx("hike.gpx", {{"Hike", {east_line(kLat, kLon, 0.0, 61, 25.0, kT0, 10.0, 1000.0)}}});
  }
  CommandResult run_view(const std::string& script_text) const {
    return run_command(view() + shell_quote(hike()) + kStyle + " --size 480x270 --script " +
                       shell_quote(script(script_text)) + " 2>&1");
  }
};

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// ffprobe's codec, size and decoded frame count of the first video stream.
std::string probe(const std::string& path) {
  return run_command(
             "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
             "stream=codec_name,width,height,nb_read_frames -of csv=p=0 " +
             shell_quote(path) + " 2>&1")
      .out;
}

bool have_ffprobe() { return run_command("ffprobe -version >/dev/null 2>&1").status == 0; }

void expect_no_temporary_files(const FilmEnv& env) {
  for (const auto& entry : std::filesystem::directory_iterator(env.home.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(ViewFilmCli, RecordFilmIsTheVideoCommandsFilm) {
  if (!have_ffprobe()) GTEST_FAIL() << "ffprobe is missing (scripts/setup.sh installs ffmpeg)";
  FilmEnv env;
  const std::string webm = env.file("viewer.webm"), mp4 = env.file("viewer.mp4");
  const auto r =
      env.run_view("film-size 320 180\nfilm-fps 10\nrecord-film " + webm + " 1\nrecord-film " + mp4 + " 1.2\n");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("wrote " + webm + " (10 frames 320x180 at 10 fps"), std::string::npos) << r.out;
  EXPECT_EQ(probe(mp4), "h264,320,180,12\n");
  EXPECT_EQ(probe(webm), "vp9,320,180,10\n");
  expect_no_temporary_files(env);
  // The same film from the command line: the same camera following the track, the same trail,
  // markers, gauges and clock.
  const std::string reference = env.file("video.webm");
  const auto v = run_command(env.video() + shell_quote(env.hike()) + kStyle +
                             " --size 320x180 --fps 10 --duration 1s -o " + shell_quote(reference) + " 2>&1");
  ASSERT_EQ(v.status, 0) << v.out;
  const std::string film = bytes(webm);
  EXPECT_GT(film.size(), 1000u);
  EXPECT_TRUE(film == bytes(reference)) << "the viewer's film differs from `trailray video`'s";
  // ... and not by chance: the track drawn in blue gives another film.
  const std::string blue = env.file("blue.webm");
  std::string options = kStyle;
  options.replace(options.find("#ff0000"), 7, "#0000ff");
  ASSERT_EQ(run_command(env.video() + shell_quote(env.hike()) + options + " --size 320x180 --fps 10 --duration 1s -o " +
                        shell_quote(blue) + " 2>&1")
                .status,
            0);
  EXPECT_FALSE(film == bytes(blue));
}

// ImGui's progress bar fill (the default dark style's PlotHistogram colour, 0.90 0.70 0.00).
bool progress_yellow(const Picture::Rgb& p) { return p.r > 200 && p.g > 150 && p.g < 200 && p.b < 40; }

TEST(ViewFilmCli, TheWindowShowsTheProgressAndCancelLeavesNoFile) {
  FilmEnv env;
  const std::string out = env.file("long.mp4"), panel = env.file("panel.png");
  const auto r = env.run_view("film-size 320 180\nfilm-fps 10\nstart-film " + out + " 60\nwait 3\nwindow-screenshot " +
                              panel + "\nwait 1\ncancel-film\nwait 1\n");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("cancelled after"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("of 600 frames: " + out + " not written"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
  expect_no_temporary_files(env);
  // While it recorded, the film window showed its progress bar, partly filled.
  const Picture p = read_picture(panel);
  std::size_t yellow = 0;
  for (std::uint32_t y = 0; y < p.height; ++y)
    for (std::uint32_t x = 0; x < p.width; ++x) yellow += progress_yellow(p.at(x, y)) ? 1 : 0;
  EXPECT_GT(yellow, 8u) << "no progress bar in " << panel;
}

// Ctrl-C in the terminal while a film records: the viewer stops between frames, cancels the film
// (no file, no temporary) and exits with 130. Only trailray gets the signal, not the X server.
TEST(ViewFilmCli, CtrlCWhileRecordingLeavesNoFile) {
  FilmEnv env;
  const std::string out = env.file("long.mp4");
  std::string view = env.prefix();
  view.replace(view.find(" render "), 8, " view ");
  const std::string inner = view + shell_quote(env.hike()) + kStyle + " --size 320x180 --script " +
                            shell_quote(env.script("film-size 160 90\nstart-film " + out + " 600\nwait 100000\n")) +
                            " & pid=$!; dir=" + shell_quote(env.home.path().string()) +
                            // Once the film's temporary file is there (the film has started), the
                            // signal; then at most 20 s for the viewer to end before a kill.
                            "; i=0; while ! ls -a \"$dir\" | grep -q '[.]tmp-' && [ $i -lt 300 ]; do sleep 0.2; "
                            "i=$((i+1)); done; kill -INT $pid; i=0; while kill -0 $pid 2>/dev/null && [ $i -lt 100 ]; "
                            "do sleep 0.2; i=$((i+1)); done; kill -KILL $pid 2>/dev/null; wait $pid; "
                            "echo \"exit status $?\"";
  const auto r = run_command(xvfb_command_prefix(env.file("Xauthority")) + "sh -c " + shell_quote(inner) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("exit status 130"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cancelled after"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
  expect_no_temporary_files(env);
}

TEST(ViewFilmCli, AnExistingFilmIsNotOverwritten) {
  FilmEnv env;
  const std::string out = env.file("earlier.mp4");
  std::ofstream(out) << "an earlier film";
  const auto r = env.run_view("film-size 320 180\nrecord-film " + out + " 1\n");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("script.txt:2:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("already exists"), std::string::npos) << r.out;
  EXPECT_EQ(bytes(out), "an earlier film");
}

}  // namespace
}  // namespace trailray::test
