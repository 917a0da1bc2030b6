// Whether a surface of the track overlay lies behind a track the G-buffer shows (track_pass.hpp,
// draw_overlay): the overlay's depth starts cleared, so where the nearest visible track stands
// in front of the terrain (by visibility_alpha's margin), a ghost, fringe or curtain farther
// along the pixel's ray than that track is dropped here, in the shader, as the depth test
// against the visible tracks' depth once dropped it. A visible hit of the track itself (about
// the same distance) stays, so that it still replaces a curtain behind it. Where a track lies
// within the margin of the terrain or in it, the overlay draws it itself and nothing is dropped.
// Needs gbuffer.glsl.

uniform highp sampler2D u_frame_distance;  // the G-buffer's distance, with the visible tracks
uniform bool u_test_visible_tracks;         // false: the overlay traces every capsule (no split)

// The distance of the visible track this pixel keeps in front of `terrain` (0: none).
float visible_track_distance(float terrain, bool packed_distance) {
  if (!u_test_visible_tracks) return 0.0;
  float d = read_distance(u_frame_distance, ivec2(gl_FragCoord.xy), packed_distance);
  bool kept = d > 0.0 && (terrain <= 0.0 || d < terrain - (0.07 + d * d * u_depth_step_k));
  return kept ? d : 0.0;
}

// Whether `t` metres along the ray lies behind that track (0: there is none) by more than the
// depth buffer's resolution there.
bool behind_visible_track(float t, float visible) {
  return visible > 0.0 && t > visible + (0.07 + visible * visible * u_depth_step_k);
}
