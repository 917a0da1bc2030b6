// The options `render` and `video` share (app/options/picture_options): both commands take every one of
// them, parse them into the same fields, and refuse the same bad values by the same name.

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/pictures/render_options.hpp"
#include "app/video/video_options.hpp"

namespace trailray::app {
namespace {

std::set<std::string> option_names(const CLI::App& cmd) {
  std::set<std::string> names;
  for (const CLI::Option* o : cmd.get_options()) names.insert(o->get_name());
  return names;
}

// Parses `words` (the command's own required words come first) into the command's args.
template <typename Args, typename Add>
Args parsed(Add add, std::vector<std::string> words) {
  CLI::App cmd;
  Args args;
  add(cmd, args);
  std::reverse(words.begin(), words.end());  // CLI11 takes the arguments last first
  cmd.parse(words);
  return args;
}

const std::vector<std::string> kShared = {
    "--size", "640x360", "--pixel-ratio", "2",           "--timeout",  "7.5",   "--verbose",
    "--look-at", "46.7,7.8,900", "--distance", "5200", "--heading", "30", "--pitch", "-24",
    "--color-by", "speed", "--terrain", "dem.tif", "--imagery", "none", "--no-shadows"};

TEST(PictureOptions, RenderAndVideoTakeTheSameSharedOptions) {
  CLI::App render_cmd, video_cmd;
  RenderArgs r;
  VideoArgs v;
  add_render_options(render_cmd, r);
  add_video_options(video_cmd, v);
  CLI::App shared_cmd;
  PictureArgs p("1x1");
  add_picture_options(shared_cmd, p, {"a", "b", "c", "d"});
  const auto shared = option_names(shared_cmd);
  ASSERT_GT(shared.size(), 30u) << "the shared group is the bulk of both commands' options";
  const auto in_render = option_names(render_cmd), in_video = option_names(video_cmd);
  for (const auto& name : shared) {
    EXPECT_TRUE(in_render.count(name)) << "render lacks " << name;
    EXPECT_TRUE(in_video.count(name)) << "video lacks " << name;
  }
  // Each command's own options stay its own.
  EXPECT_TRUE(in_render.count("--profile"));
  EXPECT_FALSE(in_video.count("--profile"));
  EXPECT_TRUE(in_video.count("--crf"));
  EXPECT_FALSE(in_render.count("--crf"));
}

TEST(PictureOptions, BothCommandsParseThemIntoTheSameFields) {
  std::vector<std::string> render_words = kShared;
  render_words.insert(render_words.end(), {"-o", "out.png", "track.gpx"});
  std::vector<std::string> video_words = kShared;
  video_words.insert(video_words.end(), {"-o", "out.mp4", "track.gpx"});
  const RenderArgs r = parsed<RenderArgs>(add_render_options, render_words);
  const VideoArgs v = parsed<VideoArgs>(add_video_options, video_words);
  for (const PictureArgs* a : {static_cast<const PictureArgs*>(&r), static_cast<const PictureArgs*>(&v)}) {
    EXPECT_EQ(a->size, "640x360");
    EXPECT_EQ(a->pixel_ratio, 2.0);
    EXPECT_EQ(a->timeout_s, 7.5);
    EXPECT_TRUE(a->verbose);
    EXPECT_EQ(a->camera.look_at, "46.7,7.8,900");
    EXPECT_EQ(a->camera.distance_m, 5200.0);
    EXPECT_EQ(a->camera.pitch_deg, -24.0);
    EXPECT_EQ(a->style.color_by, "speed");
    EXPECT_TRUE(a->style.no_shadows);
    EXPECT_EQ(a->terrain.terrain, "dem.tif");
    EXPECT_EQ(a->terrain.imagery, "none");
  }
  EXPECT_EQ(timeout_of(r).count(), 7500);
  EXPECT_EQ(r.output, "out.png");
  EXPECT_EQ(v.output, "out.mp4");
}

TEST(PictureOptions, EachCommandKeepsItsDefaultSize) {
  EXPECT_EQ(RenderArgs{}.size, "1920x1080");
  EXPECT_EQ(VideoArgs{}.size, "1280x720");
}

TEST(PictureOptions, BadSharedValuesAreRefusedByNameInBoth) {
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
           {"--pixel-ratio", "9"}, {"--pixel-ratio", "0.1"}, {"--timeout", "0"}, {"--timeout", "-3"}}) {
    RenderArgs r = parsed<RenderArgs>(add_render_options, {option, value, "-o", "out.png", "t.gpx"});
    VideoArgs v = parsed<VideoArgs>(add_video_options, {option, value, "-o", "out.mp4", "t.gpx"});
    try {
      check_render_args(r);
      ADD_FAILURE() << "render took " << option << " " << value;
    } catch (const CLI::ValidationError& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
    try {
      check_video_args(v);
      ADD_FAILURE() << "video took " << option << " " << value;
    } catch (const CLI::ValidationError& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace trailray::app
