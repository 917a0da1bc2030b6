#pragma once
// Running a peer program (gpsbabel, GDAL's Python) from a conformance test: a shell-quoted
// argument, and a command's standard output with whether it exited 0.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace trailray::test {

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline bool run_command(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return false;
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace trailray::test
