#pragma once
// `trailray serve` run by the tests as a user runs it: a child process with a private config and
// cache (a user's own must not leak in), its first line of standard output read for the URL, its
// standard error kept in a file, stopped by a signal and its exit status checked.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "terrain/tile_fixtures.hpp"

extern char** environ;

namespace trailray::test {

class ServeProcess {
 public:
  // Starts `trailray serve ARGS...` (`command` instead of "serve" for other commands) and waits up
  // to `wait_s` for its first line. started() is false when it exited or printed nothing first.
  explicit ServeProcess(const std::vector<std::string>& args, double wait_s = 60.0) {
    const std::filesystem::path stderr_path = home_.path() / "stderr.txt";
    int out[2];
    if (::pipe(out) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argv_s{TRAILRAY_BINARY, "serve"};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_s;
    for (char** e = environ; *e != nullptr; ++e) {
      const std::string entry(*e);
      if (entry.starts_with("XDG_CONFIG_HOME=") || entry.starts_with("XDG_CACHE_HOME=") ||
          entry.starts_with("TRAILRAY_CONFIG="))
        continue;
      env_s.push_back(entry);
    }
    env_s.push_back("XDG_CONFIG_HOME=" + (home_.path() / "config").string());
    env_s.push_back("XDG_CACHE_HOME=" + (home_.path() / "cache").string());
    env_s.push_back("TRAILRAY_CONFIG=");
    std::vector<char*> envp;
    for (auto& e : env_s) envp.push_back(e.data());
    envp.push_back(nullptr);
    const int spawned = posix_spawn(&pid_, TRAILRAY_BINARY, &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    stdout_fd_ = out[0];
    stderr_path_ = stderr_path;
    if (spawned != 0) {
      pid_ = -1;
      return;
    }
    first_line_ = read_line(wait_s);
    const std::string prefix = "trailray: serving on http://";
    if (first_line_.starts_with(prefix)) {
      const std::size_t colon = first_line_.rfind(':');
      port_ = std::stoi(first_line_.substr(colon + 1));
    }
  }

  ~ServeProcess() {
    if (pid_ > 0 && !exit_status_) {
      ::kill(pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
    if (stdout_fd_ >= 0) ::close(stdout_fd_);
  }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  bool started() const { return port_ > 0; }
  int port() const { return port_; }
  const std::string& first_line() const { return first_line_; }

  std::string stderr_text() const {
    std::ifstream in(stderr_path_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // Sends `signal` and waits up to `wait_s` for the exit: its status, -1 if it did not exit
  // normally, nullopt if it was still running (then killed).
  std::optional<int> stop(int signal = SIGTERM, double wait_s = 30.0) {
    if (pid_ <= 0) return std::nullopt;
    if (!exit_status_) ::kill(pid_, signal);
    return wait_exit(wait_s);
  }

  // Waits for the process to end by itself (a command that fails at start).
  std::optional<int> wait_exit(double wait_s = 60.0) {
    if (exit_status_) return exit_status_;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        return exit_status_;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exit_status_ = -2;
    return std::nullopt;
  }

 private:
  std::string read_line(double wait_s) {
    std::string line;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd p{stdout_fd_, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      char c = 0;
      if (::read(stdout_fd_, &c, 1) != 1) break;  // closed: the process ended
      if (c == '\n') return line;
      line += c;
    }
    return line;
  }

  TempDir home_;
  pid_t pid_ = -1;
  int stdout_fd_ = -1;
  std::filesystem::path stderr_path_;
  std::string first_line_;
  int port_ = 0;
  std::optional<int> exit_status_;
};

}  // namespace trailray::test
