#pragma once
// The page's options: the command line's names and values (`color`, `color-by`, `width`,
// `curtain`, `look-at`/`distance`/`heading`/`pitch`, `camera`, `time`, `no-shadows`, ...), as they
// come from URL parameters, the fragment and `trailray serve`'s configuration. One parser for
// all three, so a link and a served page say the same thing the same way.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/style.hpp"
#include "scene/text/legend.hpp"
#include "terrain/sources/terrain_config.hpp"

namespace trailray::web {

struct PageOptions {
  scene::Style style;
  std::optional<scene::LookAt> look_at;          // `look-at`, with `distance`, `heading`, `pitch`
  std::optional<scene::CameraPlacement> camera;  // `camera`
  std::optional<double> time_unix_s;             // `time` (the sun's)
  // `terrain`, `imagery`: URL templates ({z} {x} {y} {-y} {s}) or "none"; by default the
  // desktop's online sources (terrain/sources/terrain_config.hpp). `terrain-encoding`, `*-max-zoom`.
  terrain::SourceSettings terrain, imagery;
  // `overlay-legend`: the colour bar of a heatmap `trailray serve --overlay` composited into its
  // imagery, as JSON {"title", "colormap", "min", "max", "ticks": [[position, label], ...]}.
  std::optional<scene::ColorLegend> overlay_legend;
  PageOptions();
};

// What applying an option changed, so the page redoes only that.
enum class OptionEffect { style, tracks, camera, sun, terrain };

// Applies `name`=`value` to `options`; the effect, or an error naming the option and the expected
// form (the option is then unchanged). Flags (`curtain`, `no-shadows`...) take "", "1", "true",
// "on", or "0", "false", "off".
struct OptionOutcome {
  std::optional<OptionEffect> effect;
  std::string error;
};
OptionOutcome apply_page_option(PageOptions& options, std::string_view name, std::string_view value);

// The options that turn `before` into `after` where the panels edit what options also set
// (color-by, colormap, width, curtain, legend, no-shadows, no-ssao, no-atmosphere), as name and
// value in the form apply_page_option reads: a panel's edit goes into the address like an option.
std::vector<std::pair<std::string, std::string>> style_option_changes(const scene::Style& before,
                                                                      const scene::Style& after);

// `value` as it goes into the address's query or fragment, so URLSearchParams reads it back
// unchanged: '%', '&', '+', space, quotes, angle brackets, controls and non-ASCII bytes are
// percent-encoded ("+" would come back as a space, "&" would cut a URL template's own query in
// two); what people read in a link ("/:,{}#=?@") stays as it is.
std::string address_value(std::string_view value);

// The options that setting `name` resets, so an earlier value of them must leave the address
// (`terrain` sets the encoding guessed from its URL and the default zoom levels).
std::vector<std::string_view> options_reset_by(std::string_view name);

}  // namespace trailray::web
