// trailray: GPS tracks in 3D on real terrain. The command line is the front door: the track
// commands run here, the others in the program beside this one that links what they need
// (app/program/program_router).
#include <malloc.h>

#include "app/program/cli.hpp"
#include "app/program/program_router.hpp"

int main(int argc, char** argv) {
  using namespace trailray::app;
  const Program program = program_for(argc, argv);
  if (program != Program::Tracks) return hand_over(program, argv);
  // A track command lives milliseconds and allocates the same large buffers again and again
  // (points, their cleaned copy, metrics per segment): keep freed memory in the heap for the
  // next one instead of handing it back to the kernel and faulting it in afresh (glibc puts
  // blocks over 128 KiB in their own mappings). 4% of `stats --json` on a 2.8 MB GPX.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
  return run_cli(argc, argv, add_track_commands);
}
