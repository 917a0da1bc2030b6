// trailray: GPS tracks in 3D on real terrain. The command line is the front door: the track
// commands run here, the others in the program beside this one that links what they need
// (app/program_router).
#include "app/cli.hpp"
#include "app/program_router.hpp"

int main(int argc, char** argv) {
  using namespace trailray::app;
  const Program program = program_for(argc, argv);
  if (program == Program::Tracks) return run_cli(argc, argv, add_track_commands);
  return hand_over(program, argv);
}
