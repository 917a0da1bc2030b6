#pragma once
// Where warnings, errors, notes and progress go: one sink handed to the code that has something
// to say. A terminal prints them to standard error (app/common/terminal_diagnostics); the viewer also
// shows errors in its window; the browser and the video encoder will route them their own way.

#include <string>
#include <vector>

namespace trailray::scene {

class Diagnostics {
 public:
  virtual ~Diagnostics() = default;
  // Something the user should know, the work goes on (a file's dropped points, a missing value).
  virtual void warning(const std::string& message) = 0;
  // Something failed (a file that cannot be read); the caller decides whether the work goes on.
  virtual void error(const std::string& message) = 0;
  // What the user asked to be told (a picture written, frame times): always shown.
  virtual void info(const std::string& message) = 0;
  // Details asked for (`--verbose`): the GL context, the camera, what was loaded.
  virtual void note(const std::string& message) { (void)message; }
  // How far long work has come, one line ("tiles: 12/40 loaded"); called often, each line
  // replacing the one before.
  virtual void progress(const std::string& status) { (void)status; }
  // The long work is over (a progress line can be cleared).
  virtual void progress_done() {}
};

// Collects everything (tests, worker threads that hand their messages over later).
class CollectedDiagnostics : public Diagnostics {
 public:
  void warning(const std::string& message) override { warnings.push_back(message); }
  void error(const std::string& message) override { errors.push_back(message); }
  void info(const std::string& message) override { infos.push_back(message); }
  void note(const std::string& message) override { notes.push_back(message); }

  std::vector<std::string> warnings, errors, infos, notes;
};

}  // namespace trailray::scene
