#pragma once
// Ctrl-C (SIGINT) and SIGTERM as a request to stop instead of killing the process, so work in
// progress can be cleaned up (a film's temporary file removed) before the program ends.

namespace trailray::app {

// While one lives, SIGINT and SIGTERM set a flag instead of ending the process; the handlers
// that were there before are back when it goes. One at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

// Whether a SIGINT or SIGTERM came since the living guard was made.
bool interrupt_requested();

}  // namespace trailray::app
