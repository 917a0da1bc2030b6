// A mistyped option is named first, with the nearest one that exists (app/program/option_suggestion).
#include "app/program/option_suggestion.hpp"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include "app/run_command.hpp"

using namespace trailray;

namespace {

std::optional<std::string> message(const CLI::App& app, std::vector<const char*> args) {
  args.insert(args.begin(), "trailray");
  return app::unknown_option_message(app, static_cast<int>(args.size()), args.data());
}

}  // namespace

TEST(OptionSuggestion, EditDistanceCountsSwapsAsOneEdit) {
  EXPECT_EQ(app::edit_distance("--colr-by", "--color-by"), 1u);
  EXPECT_EQ(app::edit_distance("--clolr-by", "--color-by"), 2u);
  EXPECT_EQ(app::edit_distance("--ouptut", "--output"), 1u);
  EXPECT_EQ(app::edit_distance("", "abc"), 3u);
  EXPECT_EQ(app::edit_distance("same", "same"), 0u);
}

TEST(OptionSuggestion, TheFirstUnknownOptionOfTheCommandIsNamedWithTheNearest) {
  CLI::App app;
  std::string output, color_by, size;
  CLI::App* render = app.add_subcommand("render");
  render->add_option("-o,--output", output)->required();
  render->add_option("--color-by", color_by);
  render->add_option("--size", size);
  EXPECT_EQ(message(app, {"render", "--colr-by", "speed", "x.gpx"}),
            std::optional<std::string>("render: unknown option --colr-by (did you mean --color-by?)"));
  EXPECT_EQ(message(app, {"render", "--sise=10x10", "-o", "x.png"}),
            std::optional<std::string>("render: unknown option --sise (did you mean --size?)"));
  // Far from every option: named without a guess.
  EXPECT_EQ(message(app, {"render", "--terrain-exaggeration", "2"}),
            std::optional<std::string>("render: unknown option --terrain-exaggeration"));
  // Known options, values, positional arguments after "--", and no command: nothing to say.
  EXPECT_FALSE(message(app, {"render", "--color-by=speed", "-o", "x.png", "--size", "9x9", "a.gpx"}));
  EXPECT_FALSE(message(app, {"render", "-o", "x.png", "--", "--not-an-option.gpx"}));
  EXPECT_FALSE(message(app, {"--version"}));
  EXPECT_FALSE(message(app, {"rendr", "--colr-by"}));
  EXPECT_FALSE(message(app, {"render", "--help"}));
  // A command of a command has options of its own.
  int frames = 0;
  CLI::App* tracks = app.add_subcommand("bench")->add_subcommand("tracks");
  tracks->add_option("--frames", frames);
  EXPECT_FALSE(message(app, {"bench", "tracks", "--frames", "3"}));
  EXPECT_EQ(message(app, {"bench", "tracks", "--frame", "3"}),
            std::optional<std::string>("tracks: unknown option --frame (did you mean --frames?)"));
}

TEST(OptionSuggestion, TheProgramSaysItBeforeAMissingOutput) {
  const auto r = test::run_command(test::shell_quote(TRAILRAY_BINARY) + " render --colr-by speed x.gpx 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown option --colr-by (did you mean --color-by?)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("--output is required"), std::string::npos) << r.out;
}
