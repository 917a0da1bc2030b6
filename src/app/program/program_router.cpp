#include "app/program/program_router.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

namespace trailray::app {
namespace {

bool any_of(std::string_view word, std::initializer_list<std::string_view> words) {
  for (std::string_view w : words)
    if (word == w) return true;
  return false;
}

bool asks_for_help(std::string_view a) { return a == "-h" || a == "--help" || a == "--help-all"; }

// check's options that need the terrain layer (add_terrain_options).
bool terrain_option(std::string_view a) {
  return a.starts_with("--terrain") || a.starts_with("--offline") || a.starts_with("--config");
}

}  // namespace

Program program_for(int argc, const char* const* argv) {
  if (argc < 2) return Program::Full;  // the usage, with every command
  const std::string_view command = argv[1];
  if (command == "--version") return Program::Tracks;
  if (any_of(command, {"render", "elevation", "heatmap", "bench"})) return Program::Pictures;
  if (!any_of(command, {"stats", "convert", "score", "flight", "task", "check"})) return Program::Full;
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--") break;  // what follows are file names
    // check's help and terrain options are trailray-render's (it has the terrain layer).
    if (command == "check" && (terrain_option(a) || asks_for_help(a))) return Program::Pictures;
  }
  return Program::Tracks;
}

const char* program_file(Program program) {
  switch (program) {
    case Program::Tracks:
      return "trailray";
    case Program::Pictures:
      return "trailray-render";
    case Program::Full:
      return "trailray-full";
  }
  return "trailray-full";
}

int hand_over(Program program, char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path target = (ec ? std::filesystem::path(argv[0]).parent_path() : self.parent_path()) /
                                       program_file(program);
  ::execv(target.c_str(), argv);
  const int error = errno;
  std::fprintf(stderr, "trailray: error: cannot run %s: %s (it is built and installed beside trailray)\n",
               target.c_str(), std::strerror(error));
  return 127;
}

}  // namespace trailray::app
