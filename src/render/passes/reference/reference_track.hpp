#pragma once
// What the bench's two reference techniques (ribbon_pass.hpp, tube_pass.hpp) share: the origin
// their float vertices are offsets from, and the G-buffer draw state and uniforms of a solid
// coloured track. They exist only to be measured against the capsules of track_pass.hpp (issue
// 5, "Speed"); `trailray render` never draws them.

#include <glm/glm.hpp>

#include <cstddef>

#include "scene/camera/camera.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/track_buffer.hpp"

namespace trailray::render::reference {

// The mean of every point of the geometry (ECEF), so float offsets from it stay small; the
// Earth's centre for a geometry without points.
glm::dvec3 geometry_origin(const scene::TrackGeometry& geometry);

std::size_t geometry_point_count(const scene::TrackGeometry& geometry);

// The tube radius (metres) that looks `width_px` wide at `distance_m` from `camera` (the same
// width as a constant-pixel-width track there): width_px / 2 * distance / focal length in pixels.
double radius_for_pixel_width(const scene::Camera& camera, double distance_m, double width_px);

// Depth test and depth writes on, no blending, no culling (ribbons and tubes are seen from
// either side); sets the uniforms reference_track.frag and the vertex shaders share: the
// camera-relative matrix and offset of `origin`, the view rotation, the colour and the
// G-buffer's distance encoding. Leaves `program` in use.
void begin_reference_draw(const ShaderProgram& program, const GBuffer& gbuffer, const scene::Camera& camera,
                          const glm::dvec3& origin, const glm::vec3& color_srgb);

// Resets the draw state and throws RenderError naming `what` when GL reported an error.
void end_reference_draw(const char* what);

}  // namespace trailray::render::reference
