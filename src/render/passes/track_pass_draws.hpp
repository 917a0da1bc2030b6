#pragma once
// What the track pass's two files share (track_pass.cpp: the visible and shadow draws;
// track_overlay_pass.cpp: the overlay): texture units, the uniforms every capsule program takes,
// and the chunked draw of a track's capsules. Internal to render/passes.

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/track_pass.hpp"

namespace trailray::render::track_pass_detail {

// Texture units of the track programs.
constexpr GLuint kPointsUnit = 0, kBlocksUnit = 1, kColormapUnit = 2, kTerrainDistanceUnit = 3, kDropsUnit = 4,
                 kTerrainNormalUnit = 5, kFrameDistanceUnit = 6, kLodUnit = 7;
// The quad's margin for the anti-aliased fringe (pixels), and the shadow quad's (texels).
constexpr float kFringeMarginPx = 1.0f;  // the fringe reaches half a pixel past the silhouette
constexpr float kShadowMarginTexels = 1.0f;
// Capsules per draw call: the shared index buffer's 16-bit indices reach 4 * 16384 vertices.
constexpr std::int32_t kCapsulesPerDraw = 16384;

void check_gl(const char* what);  // throws RenderError naming `what` on a GL error
void set_vec3(const ShaderProgram& program, std::string_view name, const glm::vec3& v);
std::array<float, 9> to_float_mat3(const glm::dmat3& m);
// Uniforms every capsule program shares: the camera's pixel size and vertical.
void set_width_uniforms(const ShaderProgram& program, const scene::Camera& camera);
// A draw's own shape (track_pass.hpp CapsuleShape): width, dashes, the raised last points.
void set_shape_uniforms(const ShaderProgram& program, const TrackDraw& draw, const TrackSceneSettings& settings);
// k of the shaders' "d * d * k": the depth buffer's resolution at distance d.
float depth_step_k(const scene::Camera& camera);
void set_color_uniforms(const ShaderProgram& program, const TrackDraw& draw, const TrackSceneSettings& settings);
void bind_texture(GLuint unit, const Texture& texture);
// The index buffer every capsule draw shares (0 1 2 2 1 3 per quad).
Buffer make_quad_indices();
// The level of detail a draw's capsules take for a camera (TrackLod::View), or nullopt: full
// detail (LOD off in the settings, or pins and dashed routes, whose points all matter).
std::optional<TrackLod::View> lod_view_for(const scene::Camera& camera, const TrackDraw& draw,
                                           const TrackSceneSettings& settings);
// Draws every capsule of the track in chunks of kCapsulesPerDraw (the quads' vertex array bound),
// through the level of detail when `lod` is given; returns the capsules drawn.
std::size_t draw_segments(const ShaderProgram& program, const TrackBuffer& buffer,
                          CapsuleShape::Capsules capsules = CapsuleShape::Capsules::polyline,
                          const std::optional<TrackLod::View>& lod = std::nullopt);
bool drawable(const TrackDraw& draw);

}  // namespace trailray::render::track_pass_detail
