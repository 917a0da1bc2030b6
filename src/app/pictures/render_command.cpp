#include "app/pictures/render_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/pictures/render_options.hpp"
#include "app/pictures/render_picture.hpp"

namespace trailray::app {
namespace {

// parse -> scene -> draw (render_picture) -> output.
int run_render(const RenderArgs& a) {
  TerminalDiagnostics diagnostics(a.verbose);
  const scene::RgbaImage image = render_picture(a, diagnostics);
  scene::write_srgb_png(a.output, image);
  diagnostics.note(fmt::format("wrote {} ({}x{})", a.output, image.width, image.height));
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd =
      app.add_subcommand("render", "A picture of tracks on the terrain, or of the terrain from a camera, as a PNG");
  add_render_options(*cmd, *args);
  cmd->callback([args, &exit_code] {
    args->tracks = expand_track_arguments(args->tracks);
    exit_code = run_render(*args);
  });
}

}  // namespace trailray::app
