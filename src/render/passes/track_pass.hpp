#pragma once
// The track pass (DESIGN.md "The frame", step 4; thesis §3.2, improved): every segment between
// two consecutive points of a track is a capsule (a cylinder with round ends), drawn as one
// camera-facing quad built from gl_VertexID (Groß and Gumhold's tight bounding quad) and ray
// traced in the fragment shader, which writes the exact normal and gl_FragDepth from the hit.
//
// Joints: the planes through each joint (thesis eq. 3.7) split the overlap of consecutive
// capsules; a hit is clipped by a plane only where the neighbouring capsule holds it, so a
// sharp turn (up to a 180 degree reversal) or a repeated point never leaves a hole, and the
// union of the capsules is drawn once per pixel (no double blending when translucent).
//
// Three draws per frame, each over every segment:
//   visible  into the G-buffer (albedo, normal, distance, depth-tested against the terrain), so
//            the sun, the shadows and SSAO light the tracks like the terrain;
//            where the terrain passes through a tube (a track lying on the ground) it does not
//            hide it: those hits are drawn here too, in front of the terrain (track_trace.glsl,
//            terrain_inside_tube), from a copy of the terrain's distances and normals;
//   overlay  into the overlay target (premultiplied RGBA8 + depth): hits behind the terrain as
//            translucent "ghosts" (constant alpha down to fade_near_m behind the terrain, fading
//            to 0 at fade_far_m), the anti-aliased silhouette fringe of visible tubes, and the
//            curtains; blended over the composed frame once (blend_overlay). After the visible
//            draw: what lies behind a visible track of the G-buffer is dropped (by a depth
//            prefilled from the G-buffer where many capsules overlap, else by a texel and a test
//            in the shaders: OverlayDepth), so a capsule that stands above all the terrain drawn
//            (no ghost possible) only adds its fringe; only the others are ray traced again
//            (hidden parts cost only where the terrain may hide a track);
//   shadow   capsules ray traced along the sun's direction into the cascaded shadow maps: the
//            tracks cast shadows on the terrain.

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/capsule_shape.hpp"
#include "render/passes/compose_pass.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pieces.hpp"
#include "scene/camera/camera.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene/style.hpp"
#include "track/color_values.hpp"

namespace trailray::render {

// One track of a buffer that holds many (TrackBuffer::Range::track).
struct TrackDrawStyle {
  glm::vec3 color_srgb{0.9f, 0.1f, 0.1f};
  bool by_value = false;
  bool visible = true;  // hidden tracks' pieces are left out of the frame's table
};

struct TrackDraw {
  const TrackBuffer* buffer = nullptr;
  glm::vec3 color_srgb{0.9f, 0.1f, 0.1f};  // the solid colour (when not by value)
  bool by_value = false;                   // colour by the buffer's values through the scale
  CapsuleShape shape;
  bool is_pin = false;  // a waypoint's stem or ball (not counted as a track)
  // A buffer of many tracks: each track's own colour and visibility, indexed by the segments'
  // Range::track (color_srgb and by_value are then unused). Empty: one track, the fields above.
  std::span<const TrackDrawStyle> track_styles;
  // Whether a track of the buffer (Range::track) is shown: always without track_styles.
  bool shows_track(std::int32_t track) const;
  // How many of its tracks are shown (counted as tracks drawn).
  std::size_t shown_tracks() const;
};

enum class OverlayDepth { chosen, prefilled, tested_in_shaders };

// The pass's settings: a scene's track style with its colour scale (track_settings_for).
struct TrackSceneSettings {
  scene::TrackWidth width;
  double min_width_px = 1.5;  // a distant tube never gets thinner than this (no dotted tracks)
  scene::TrackOcclusion occlusion;
  bool curtain = false;  // `--curtain`: a translucent wall down to the ground
  float curtain_alpha = 0.3f;
  scene::Colormap colormap = scene::Colormap::turbo;
  float value_min = 0.0f, value_max = 1.0f;  // the colour scale's range
  bool cast_shadows = true;
  // The highest terrain drawn (metres above the ellipsoid): the overlay then ray traces only the
  // capsules this terrain may hide, and draws the fringe of the others without a ray test where a
  // visible tube covers it (draw_overlay). Unset: it traces every fragment of every capsule.
  std::optional<double> terrain_top_m;
  // Level of detail (track_lod.hpp): consecutive capsules shorter than about a pixel are drawn as
  // one, within half a pixel and 1/32 of the colour scale. false: every capsule (tests, bench).
  bool level_of_detail = true;
  // With terrain_top_m, how the overlay drops what lies behind a visible track (draw_overlay):
  // chosen per frame by the capsules drawn, or always one way (tests, bench).
  OverlayDepth overlay_depth = OverlayDepth::chosen;
};

// The settings for a track style and the colour scale in use (nullopt: solid colours).
TrackSceneSettings track_settings_for(const scene::TrackStyle& style, const std::optional<track::ValueRange>& range);

// The overlay target: premultiplied sRGB-encoded colour and its own depth buffer, the size of
// the frame.
class TrackOverlayTarget {
 public:
  TrackOverlayTarget(int width, int height);  // throws RenderError
  void bind_and_clear() const;                // colour (0,0,0,0), depth far, viewport
  // Binds it, clears the colour and copies the G-buffer's depth (the same size) into its own.
  void bind_with_depth_of(const GBuffer& gbuffer) const;
  int width() const { return frame_.width(); }
  int height() const { return frame_.height(); }
  const Texture& color() const { return frame_.color(); }

 private:
  ColorDepthTarget frame_;  // RGBA8 + 24-bit depth, like the composed frame
};

class TrackPass {
 public:
  TrackPass();  // compiles the programs (the GL context must be current); throws ShaderError

  // Once per frame, before drawing: rewrites each buffer's block origins for the camera and
  // plans what each draw's capsules are this frame (track_pieces.hpp: the level of detail's runs
  // of the shown tracks), which the visible, overlay and shadow draws then share.
  void prepare(std::span<const TrackDraw> tracks, const scene::Camera& camera, const TrackSceneSettings& settings);

  // Into the G-buffer (as TerrainPass left it: the terrain's depth in the depth buffer, no
  // tracks yet); binds it.
  void draw_visible(const GBuffer& gbuffer, const scene::Camera& camera, std::span<const TrackDraw> tracks,
                    const TrackSceneSettings& settings) const;

  // Clears and fills `target`; call after draw_visible, whose copy of the terrain's distance and
  // normal it reads, and whose depth it starts from.
  void draw_overlay(const GBuffer& gbuffer, const TrackOverlayTarget& target, const scene::Camera& camera,
                    const SceneLighting& lighting, std::span<const TrackDraw> tracks,
                    const TrackSceneSettings& settings) const;

  // Blends the overlay over the bound framebuffer (the composed frame).
  void blend_overlay(const TrackOverlayTarget& target) const;

  // The capsules the last draw_visible drew (with the level of detail, fewer than the segments).
  std::size_t visible_capsules() const { return visible_capsules_; }

  // Inside ShadowMaps::render's callback: the capsules as casters for one cascade.
  // `light_view_projection` is the callback's camera-relative matrix, `towards_sun_ecef` a unit
  // vector, `texel_m` the size of one of the cascade's texels (the quads' margin). The tubes
  // keep the radius the camera sees them with, so shadow and tube agree.
  // `may_hold` (the cascade's ShadowCascade::may_hold) leaves out the tracks of a many-track
  // buffer that cannot reach the cascade.
  using SphereTest = std::function<bool(const glm::dvec3& centre_ecef, double radius_m)>;
  void draw_shadow_casters(const std::array<float, 16>& light_view_projection, const glm::dvec3& towards_sun_ecef,
                           double texel_m, const scene::Camera& camera, std::span<const TrackDraw> tracks,
                           const TrackSceneSettings& settings, const SphereTest& may_hold = {}) const;

 private:
  ShaderProgram visible_, overlay_, fringe_, prefill_, shadow_, curtain_, blend_;
  VertexArray empty_;  // no attributes: everything comes from gl_VertexID
  VertexArray quads_;  // no attributes either, but the shared quad index buffer
  Buffer quad_indices_;
  mutable Texture colormap_;  // 256x1 SRGB8_ALPHA8, remade when the map changes
  mutable std::optional<scene::Colormap> colormap_loaded_;
  void bind_colormap(scene::Colormap map, GLuint unit) const;
  // The terrain's distance and normal, copied out of the G-buffer for draw_visible, which reads
  // them while it writes the G-buffer (sampling an attached texture would be a feedback loop).
  // Remade when the frame's size or distance encoding changes.
  struct TerrainCopy {
    Texture distance, normal;
    Framebuffer source, target;  // reads the G-buffer's textures; draws into the copies
    int width = 0, height = 0;
    bool packed = false;
  };
  mutable TerrainCopy terrain_copy_;
  mutable std::size_t visible_capsules_ = 0;
  // The frame's plan per draw (prepare): its piece table and its tracks' styles on the GPU.
  struct FramePieces {
    CapsulePieces pieces;
    Texture table;   // RGBA32I, three texels per piece (CapsulePieces::texels)
    Texture styles;  // RGBA32F, per track: linear colour, 1 when by value
  };
  struct PiecesKey {
    const TrackBuffer* buffer = nullptr;
    int capsules = 0;  // CapsuleShape::Capsules
    bool operator==(const PiecesKey&) const = default;
  };
  struct PiecesKeyHash {
    std::size_t operator()(const PiecesKey& k) const noexcept {
      return std::hash<const void*>{}(k.buffer) * 3u + static_cast<std::size_t>(k.capsules);
    }
  };
  std::unordered_map<PiecesKey, FramePieces, PiecesKeyHash> frame_pieces_;
  const FramePieces& prepared(const TrackDraw& draw) const;  // throws RenderError when not prepared
  // Binds a prepared draw's tables and draws its pieces with `program` (else `only`'s, a subset
  // with its own table); returns the capsules.
  std::size_t draw_pieces(const ShaderProgram& program, const TrackDraw& draw,
                          const std::pair<const CapsulePieces*, const Texture*>& only = {}) const;
  void copy_terrain(const GBuffer& gbuffer) const;
  // The overlay's depth from the G-buffer's visible tracks (overlay_prefill.frag).
  void prefill_overlay_depth(const GBuffer& gbuffer, const TrackOverlayTarget& target, const scene::Camera& camera,
                             std::span<const TrackDraw> tracks, const TrackSceneSettings& settings) const;
  // Whether this frame's overlay starts from that depth (TrackSceneSettings::overlay_depth).
  bool prefills_overlay_depth(const GBuffer& gbuffer, const TrackSceneSettings& settings) const;
  // The uniforms the overlay's two programs share.
  void set_overlay_uniforms(const ShaderProgram& program, const GBuffer& gbuffer, const scene::Camera& camera,
                            const SceneLighting& lighting, const TrackSceneSettings& settings,
                            const std::array<float, 16>& view_projection) const;
  // The curtains into the bound overlay target (blended; its depth hides those behind tubes).
  void draw_curtains(const GBuffer& gbuffer, const scene::Camera& camera, const SceneLighting& lighting,
                     std::span<const TrackDraw> tracks, const TrackSceneSettings& settings,
                     const std::array<float, 16>& view_projection) const;
};

}  // namespace trailray::render
