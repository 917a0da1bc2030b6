// The prefix that runs a viewer command in a virtual X server of its own (Debian xvfb).
#pragma once

#include <unistd.h>

#include <fstream>
#include <string>

#include "run_command.hpp"

namespace trailray::test {

// `xvfb-run -a` looks for a free display from :99 by its lock file and then starts the server:
// two tests starting at once (ctest -j) can both pick the same number and one fails. Each test
// process starts its search at a number of its own (from its process id), so they rarely meet.
// The X authority file is the test's own: xvfb-run's temporary folder sometimes fails to clean
// up (exit 5) when the program ends quickly. Under the sanitizers, no leak check for the window:
// the window system (Xlib, Mesa's X11 code) keeps two blocks at exit whose stacks the fast
// unwinder cannot follow into a driver library that tests/lsan.supp could name, and the full
// unwinder deadlocks there. ASan and UBSan still watch every access; the renderer's allocations
// are leak-checked through `trailray render`. No effect without sanitizers.
inline std::string xvfb_command_prefix(const std::string& auth_file) {
  std::ofstream(auth_file, std::ios::app).flush();
  const int first_display = 100 + static_cast<int>(::getpid() % 4000) * 2;
  return "xvfb-run -n " + std::to_string(first_display) + " -a -f " + shell_quote(auth_file) +
         " env \"ASAN_OPTIONS=${ASAN_OPTIONS}:detect_leaks=0\" ";
}

}  // namespace trailray::test
