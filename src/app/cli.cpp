#include "app/cli.hpp"

namespace trailray::app {

int run_cli(int, char**) { return 0; }

}  // namespace trailray::app
