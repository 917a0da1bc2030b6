#include "app/program/option_suggestion.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace trailray::app {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Damerau-Levenshtein (optimal string alignment): a swapped pair of letters is one edit.
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::optional<std::string> unknown_option_message(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* command = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;  // positional from here on
    if (command == nullptr) {
      if (arg.starts_with("-")) continue;  // --version, --help before the command
      for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub->check_name(std::string(arg))) command = sub;
      if (command == nullptr) return std::nullopt;  // not a command: the parser says so
      continue;
    }
    if (!arg.starts_with("-")) {
      // A command of the command (`bench tracks`), else a positional argument or a value.
      for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
        if (!sub->get_name().empty() && sub->check_name(std::string(arg))) command = sub;
      continue;
    }
    if (!arg.starts_with("--") || arg.size() == 2) continue;
    const std::string name(arg.substr(0, arg.find('=')));
    // Known to the command or to one it belongs to.
    bool known = false;
    for (const CLI::App* c = command; c != nullptr && !known; c = c->get_parent())
      known = c->get_option_no_throw(name) != nullptr;
    if (known) continue;
    // The nearest long option the command has, when it is near enough to be a typo.
    std::string best;
    std::size_t best_distance = 0;
    for (const CLI::Option* option : command->get_options())
      for (const std::string& long_name : option->get_lnames()) {
        const std::string candidate = "--" + long_name;
        const std::size_t distance = edit_distance(name, candidate);
        if (best.empty() || distance < best_distance) {
          best = candidate;
          best_distance = distance;
        }
      }
    const bool near = !best.empty() && best_distance <= std::max<std::size_t>(2, name.size() / 4);
    return fmt::format("{}: unknown option {}{}", command->get_name(), name,
                       near ? fmt::format(" (did you mean {}?)", best) : std::string());
  }
  return std::nullopt;
}

}  // namespace trailray::app
