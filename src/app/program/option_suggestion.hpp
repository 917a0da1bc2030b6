#pragma once
// A mistyped option named first, with the nearest that exists: `trailray render --colr-by speed
// x.gpx` answers "unknown option --colr-by (did you mean --color-by?)" rather than a complaint about
// something else the parser checks before it looks at what it did not know (CLI11 reports a
// missing --output first).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// The message for the first long option of the command line that the command it names does not
// have; nullopt when every one is known (or no command is named).
std::optional<std::string> unknown_option_message(const CLI::App& app, int argc, const char* const* argv);

// Edits (insertions, deletions, substitutions, swaps of neighbours) from one word to the other.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace trailray::app
