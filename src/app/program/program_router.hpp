#pragma once
// `trailray` is three programs, so that a command loads only the libraries it uses (start-up is
// mostly the dynamic loader's: 214 libraries took 60 ms before any work):
//   trailray         the track commands in its own process (stats, convert, score, flight, task,
//                    check without --terrain): the readers and the analysis, no terrain, GL,
//                    encoders, window or server;
//   trailray-render  render, elevation, heatmap, bench and check --terrain: the terrain layer and headless
//                    GL, no films' encoders, window or HTTP server;
//   trailray-full    view, video, serve, the help of the whole program and anything else.
// The user types `trailray COMMAND` for all of them: trailray hands the command line over to the
// program beside it (exec, the same process id), which parses it with the same definitions.

namespace trailray::app {

enum class Program { Tracks, Pictures, Full };

// Which program runs this command line.
Program program_for(int argc, const char* const* argv);

// The file name of a program beside trailray ("trailray-render", "trailray-full").
const char* program_file(Program program);

// Replaces this process with `program` run on the same arguments; returns only on failure, after
// printing an error that names the missing file (exit status 127 for the caller to return).
int hand_over(Program program, char** argv);

}  // namespace trailray::app
