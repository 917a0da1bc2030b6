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
#include <vector>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/track_pass.hpp"

namespace trailray::render::track_pass_detail {

// Texture units of the track programs.
constexpr GLuint kPointsUnit = 0, kBlocksUnit = 1, kColormapUnit = 2, kTerrainDistanceUnit = 3, kDropsUnit = 4,
                 kTerrainNormalUnit = 5, kFrameDistanceUnit = 6, kLodUnit = 7, kPiecesUnit = 8, kStylesUnit = 9;
// The quad's margin for the anti-aliased fringe (pixels), and the shadow quad's (texels).
constexpr float kFringeMarginPx = 1.0f;  // the fringe reaches half a pixel past the silhouette
constexpr float kShadowMarginTexels = 1.0f;
// Capsules per draw call: the shared index buffer's 16-bit indices reach 4 * 16384 vertices.
constexpr std::int32_t kCapsulesPerDraw = 16384;
static_assert(CapsulePieces::kPieceCapsules <= kCapsulesPerDraw);

void check_gl(const char* what);  // throws RenderError naming `what` on a GL error
void set_vec3(const ShaderProgram& program, std::string_view name, const glm::vec3& v);
std::array<float, 9> to_float_mat3(const glm::dmat3& m);
// Uniforms every capsule program shares: the camera's pixel size and vertical.
void set_width_uniforms(const ShaderProgram& program, const scene::Camera& camera);
// A draw's own shape (track_pass.hpp CapsuleShape): width, dashes, the raised last points.
void set_shape_uniforms(const ShaderProgram& program, const TrackDraw& draw, const TrackSceneSettings& settings);
// k of the shaders' "d * d * k": the depth buffer's resolution at distance d.
float depth_step_k(const scene::Camera& camera);
// The colour scale's uniforms (the solid colours come per track from the style table).
void set_scale_uniforms(const ShaderProgram& program, const TrackSceneSettings& settings);
// A draw's tracks' styles as the style table holds them: per track linear colour, 1 when by value.
std::vector<float> style_texels(const TrackDraw& draw);
glm::vec3 srgb_to_linear(const glm::vec3& c);
void bind_texture(GLuint unit, const Texture& texture);
// The index buffer every capsule draw shares (0 1 2 2 1 3 per quad).
Buffer make_quad_indices();
// The level of detail a draw's capsules take for a camera (TrackLod::View), or nullopt: full
// detail (LOD off in the settings, or pins and dashed routes, whose points all matter).
std::optional<TrackLod::View> lod_view_for(const scene::Camera& camera, const TrackDraw& draw,
                                           const TrackSceneSettings& settings);
// Binds the buffer's point, block and level-of-detail textures to their units.
void bind_buffer(const ShaderProgram& program, const TrackBuffer& buffer);
bool drawable(const TrackDraw& draw);

}  // namespace trailray::render::track_pass_detail
