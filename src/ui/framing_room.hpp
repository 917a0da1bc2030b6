#pragma once
// Where a framing may put the tracks while the panels are open at their first places (both
// viewers frame a track so that no panel covers it): right of the track list, above the profile
// chart, out of the replay panel's corner, and above the legend (or out of its corner when that
// leaves too little).

#include <optional>

#include "scene/camera/framing.hpp"
#include "ui/panel_layout.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

struct FramingRoom {
  scene::KeptClearCorner keep_clear;
  std::optional<scene::ImageArea> area;  // nullopt: all of the picture
};

// `legend`: the legend's corner in the picture (empty: none). `pixel_ratio`: picture pixels per
// interface unit (the page's device pixel ratio; the panels are laid out in interface units). A
// window too small for the panels and a view gets the legend's corner and no area.
FramingRoom panel_framing_room(const ViewerSettings& settings, const scene::Lens& lens,
                               const scene::KeptClearCorner& legend, double pixel_ratio = 1.0);
// The same for panels laid out as `layout` (interface units; the page's folded layout on a small
// window): the default layout is default_panel_layout's.
FramingRoom framing_room_beside(const PanelLayout& layout, const ViewerSettings& settings, const scene::Lens& lens,
                                const scene::KeptClearCorner& legend, double pixel_ratio);

}  // namespace trailray::ui
