#pragma once
// Runs a shell command in tests and captures its standard output and exit status.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>
#include <utility>

namespace trailray::test {

struct CommandResult {
  int status = -1;  // exit code, or -1 when it did not exit normally
  std::string out;
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 65536> buf{};
  std::size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  int st = pclose(pipe);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// A command's standard output into `out`; whether it exited 0.
inline bool run_command(const std::string& command, std::string& out) {
  CommandResult r = run_command(command);
  out = std::move(r.out);
  return r.status == 0;
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace trailray::test
