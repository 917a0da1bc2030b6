#pragma once
// The legend in the page: the one pictures get (scene::draw_scene_legend: colour bar, or key of
// track names), shown in a canvas over the WebGL one. It is drawn twice, over black and over
// white; from the two, each pixel's colour and opacity follow exactly (a = 1 - (white - black),
// colour = black / a), whatever the legend blends.

#include <cstdint>
#include <vector>

#include "scene/pictures/image_paint.hpp"
#include "scene/scene.hpp"

namespace trailray::web {

struct PageLegend {
  scene::PixelRect rect;           // where it goes in the picture (device pixels); empty: none
  std::vector<std::uint8_t> rgba;  // rect.width x rect.height, top-down, straight (not premultiplied) alpha
};

PageLegend page_legend(const scene::Scene& scene, std::uint32_t width_px, std::uint32_t height_px);

}  // namespace trailray::web
