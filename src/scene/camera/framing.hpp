#pragma once
// Automatic framing: a camera that shows a set of points (the tracks) whole, from an oblique
// angle, with the track spread across the image and terrain around it.
//
//   - heading: the camera looks along the points' short axis (the direction in which their
//     horizontal extent is smallest), so the long axis lies across the screen; where the shape
//     has no clear short axis (round, square, a single point), the preferred heading wins;
//   - pitch: fixed, -45 degrees by default (an oblique view that shows relief and height);
//   - distance: the smallest that keeps every point inside the image with the margin (found by
//     bisection on the exact projection, earth curvature included), the points' image centred,
//     and at least a minimum width of terrain in view;
//   - an area of the image (where a viewer's panels leave the view free): the points are framed
//     into it as into a whole image;
//   - a corner kept clear (where a legend will be drawn over the picture): when the centred
//     framing puts a point there, the points are moved out of it, centred in the band above (or
//     below) it or beside it, or further away, whichever shows them largest; the heading and
//     pitch stay, only the target moves (and the distance grows as little as it must).
// Framing knows no terrain: where peaks rise between the camera and the track, the caller may
// choose a steeper pitch.

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::scene {

enum class ImageCorner { top_left, top_right, bottom_left, bottom_right };

// A rectangle in a corner of the image, `width_px` x `height_px` from the corner, that no framed
// point may project into (a legend's panel and the gap wanted around it). Either size 0: none.
struct KeptClearCorner {
  ImageCorner corner = ImageCorner::bottom_left;
  double width_px = 0.0, height_px = 0.0;

  bool empty() const { return !(width_px > 0.0) || !(height_px > 0.0); }
};

// A rectangle of the image in pixels (x right, y down from the top-left corner).
struct ImageArea {
  double left_px = 0.0, top_px = 0.0, right_px = 0.0, bottom_px = 0.0;
};

struct FramingOptions {
  Lens lens;
  double pitch_deg = -45.0;            // within [-90, -5]
  double margin_fraction = 0.08;       // of the width (left, right) and height (top, bottom) kept free
  double preferred_heading_deg = 0.0;  // among equally good headings, the one closest to this
  double min_view_width_m = 2000.0;    // terrain width in view at the target, however small the track
  // The terrain height under the points, for the depth range and for points without a height;
  // NaN: the lowest point's height.
  double ground_height_m = std::numeric_limits<double>::quiet_NaN();
  // Where the points must not go. When they cannot be kept out of it (a corner nearly as large
  // as the image), the framing is the one without it.
  KeptClearCorner keep_clear;
  // The part of the image the points are framed into, with the margin inside it (a viewer's
  // panels cover the rest); nullopt: the whole image. It must lie within the image and hold its
  // centre.
  std::optional<ImageArea> area;
};

struct Framing {
  LookAt look_at;  // target (the image's centre), distance, heading and pitch
  Camera camera;
  double ground_height_m = 0.0;  // the ground it assumed under the points (FramingOptions::ground_height_m)
};

// A camera framing `points` (latitude and longitude in degrees, heights in metres; a point
// without a height, NaN, is placed on the ground). Points whose latitude or longitude is not a
// finite number within range are left out; an error when none is left or an option is out of
// range.
Result<Framing> frame_points(std::span<const GeoPosition> points, const FramingOptions& options = {});

// A camera framing tracks where they are drawn: their ECEF points as the scene placed them (no
// geodetic conversion again), the lowest recorded altitude for the ground under them when
// options.ground_height_m is not given. An error when no track has a point.
Result<Framing> frame_tracks(std::span<const Track* const> tracks, const FramingOptions& options = {});
// The visible tracks of a set.
Result<Framing> frame_tracks(const TrackSet& tracks, const FramingOptions& options = {});

// Whether the image's centre lies inside `area` less its margins (FramingOptions): framing into
// an area needs it, as the points' image shrinks toward the centre when the camera backs away.
bool area_holds_centre(const ImageArea& area, const Lens& lens, double margin_fraction);

// Tracks too far apart for one view (a pilot's flights of many years over several countries, or
// on both sides of the Earth): the visible tracks whose centres (the mean of their points) lie
// within `radius_m` of the centre of the track that has the most such neighbours (itself included) (the first of
// those in the set's order on a tie), in the set's order. Empty when no visible track has a point.
inline constexpr double kTrackGroupRadiusM = 300000.0;
std::vector<const Track*> largest_track_group(const TrackSet& tracks, double radius_m = kTrackGroupRadiusM);

}  // namespace trailray::scene
