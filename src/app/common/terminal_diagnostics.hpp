#pragma once
// The command line's diagnostics sink: warnings and errors to standard error as
// "trailray: warning: ...", what was asked for as "trailray: ...", notes only with --verbose, progress as one line
// rewritten in place, only when standard error is a terminal (a log file gets no progress noise).

#include <string>

#include "scene/diagnostics.hpp"

namespace trailray::app {

class TerminalDiagnostics : public scene::Diagnostics {
 public:
  // `verbose`: print notes. `progress`: show progress (default: when standard error is a terminal).
  explicit TerminalDiagnostics(bool verbose = false);
  TerminalDiagnostics(bool verbose, bool progress);

  void warning(const std::string& message) override;
  void error(const std::string& message) override;
  void info(const std::string& message) override;
  void note(const std::string& message) override;
  void progress(const std::string& status) override;
  void progress_done() override;

  bool verbose() const { return verbose_; }

 private:
  void clear_progress();

  bool verbose_ = false;
  bool show_progress_ = false;
  bool progress_shown_ = false;
};

}  // namespace trailray::app
