#include "app/common/terminal_diagnostics.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace trailray::app {

TerminalDiagnostics::TerminalDiagnostics(bool verbose) : TerminalDiagnostics(verbose, isatty(STDERR_FILENO) != 0) {}

TerminalDiagnostics::TerminalDiagnostics(bool verbose, bool progress) : verbose_(verbose), show_progress_(progress) {}

void TerminalDiagnostics::clear_progress() {
  if (!progress_shown_) return;
  fmt::print(stderr, "\r\x1b[K");
  progress_shown_ = false;
}

void TerminalDiagnostics::warning(const std::string& message) {
  clear_progress();
  fmt::print(stderr, "trailray: warning: {}\n", message);
}

void TerminalDiagnostics::error(const std::string& message) {
  clear_progress();
  fmt::print(stderr, "trailray: error: {}\n", message);
}

void TerminalDiagnostics::info(const std::string& message) {
  clear_progress();
  fmt::print(stderr, "trailray: {}\n", message);
}

void TerminalDiagnostics::note(const std::string& message) {
  if (!verbose_) return;
  clear_progress();
  fmt::print(stderr, "trailray: {}\n", message);
}

void TerminalDiagnostics::progress(const std::string& status) {
  if (!show_progress_) return;
  fmt::print(stderr, "\r{}\x1b[K", status);
  progress_shown_ = true;
}

void TerminalDiagnostics::progress_done() { clear_progress(); }

}  // namespace trailray::app
