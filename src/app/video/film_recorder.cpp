#include "app/video/film_recorder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/text/legend_content.hpp"

namespace trailray::app {
namespace {

// Every camera is known before the first frame: while a frame is drawn, the tiles of one a little
// later are already loading (the frame itself still waits for all of its own).
constexpr std::size_t kPrefetchFrames = 10;
void prefetch_tiles(scene::TerrainView& terrain, const scene::Camera& later, double neutral_ground_m) {
  if (terrain.heights() == nullptr && terrain.imagery() == nullptr) return;
  scene::TileLoadPolicy waiting = terrain.policy(), asking = waiting;
  asking.wait = false;
  terrain.set_policy(asking);
  terrain.tiles_for(later, neutral_ground_m);
  terrain.set_policy(std::move(waiting));
}

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

FilmSetup checked(FilmSetup setup) {
  if (setup.tracks == nullptr || setup.waypoints == nullptr || setup.terrain == nullptr)
    throw std::invalid_argument("a film needs its tracks, waypoints and terrain view");
  if (setup.cameras.empty() || setup.cameras.size() != setup.clock.timing.frames)
    throw std::invalid_argument(fmt::format("a film of {} frames needs as many cameras, not {}",
                                            setup.clock.timing.frames, setup.cameras.size()));
  for (const scene::FilmFrame& f : setup.frames)
    if (f.clock_frame >= setup.cameras.size() || (f.photo && *f.photo >= setup.photos.size()))
      throw std::invalid_argument("a film frame past the clock's frames or the photos");
  return setup;
}

}  // namespace

std::vector<std::size_t> gauged_tracks(const scene::TrackSet& tracks, FilmCameraMode mode, int follow) {
  std::vector<std::size_t> gauged;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const scene::Track& t = tracks[i];
    const bool followed = static_cast<int>(i) + 1 == follow;
    if (mode == FilmCameraMode::follow ? followed : (!t.is_route && t.start_time())) gauged.push_back(i);
  }
  return gauged;
}

std::string map_attribution(const TerrainSources& sources) {
  std::string attribution;
  for (const std::string& credit : {sources.heights ? sources.heights->info().attribution : std::string(),
                                    sources.imagery ? sources.imagery->info().attribution : std::string()})
    if (!credit.empty() && attribution.find(credit) == std::string::npos)
      attribution += (attribution.empty() ? "" : " | ") + credit;
  return attribution;
}

std::string film_progress_text(const FilmProgress& p) {
  return fmt::format("frame {}/{}  {:.2f} fps  {} left", p.done, p.total, p.frames_per_s, clock_text(p.seconds_left));
}

FilmRecorder::FilmRecorder(FilmSetup setup, std::unique_ptr<FilmWriter> writer)
    : setup_(checked(std::move(setup))),
      writer_(std::move(writer)),
      film_(*setup_.tracks, *setup_.waypoints, setup_.trail, setup_.marker_ground_m) {
  film_.set_clock_offsets(setup_.clock.offsets);
  scene_.terrain = setup_.terrain;
  if (setup_.volumes != nullptr && !setup_.volumes->volumes.empty()) scene_.volumes = setup_.volumes;
  scene_.style = setup_.style;
  scene_.color_range = setup_.color_range;
  scene_.overlay_legend = setup_.overlay_legend;
  scene_.sun_time_unix_s = setup_.sun_time_unix_s;
  scene_.neutral_ground_m = setup_.neutral_ground_m;
  // The legend lists the tracks, not their trails and ghosted futures.
  legend_scene_ = scene_;
  legend_scene_.tracks = setup_.tracks;
  picture_.pixel_ratio = setup_.pixel_ratio;
  // The mini profile (full overlay): the first gauged track's, over the part filmed.
  const scene::Lens& lens = setup_.cameras.front().lens();
  if (setup_.overlay == scene::OverlayLevel::full && !setup_.gauged.empty()) {
    const std::size_t k = setup_.gauged.front();
    const FilmClock& clock = setup_.clock;
    const scene::TimeSpan own{clock.timing.span.start + clock.offsets[k], clock.timing.span.end + clock.offsets[k]};
    profile_ = scene::film_profile((*setup_.tracks)[k], own,
                                   scene::film_profile_panel(lens.width_px, lens.height_px).width - 8);
  }
}

FilmRecorder::~FilmRecorder() = default;

bool FilmRecorder::next_frame_ready() {
  scene::TerrainView& terrain = *setup_.terrain;
  if (done() || (terrain.heights() == nullptr && terrain.imagery() == nullptr)) return true;
  scene::TileLoadPolicy asking = setup_.tiles;
  asking.wait = false;
  terrain.set_policy(asking);
  return terrain.tiles_for(setup_.cameras[next_], scene_.neutral_ground_m).report.progress.done();
}

void FilmRecorder::draw_next(render::Renderer& renderer) {
  if (done()) throw std::logic_error("the film has no more frames");
  if (writer_ == nullptr) throw std::logic_error("the film was cancelled");
  const auto start = std::chrono::steady_clock::now();
  if (!started_) started_ = start;
  // The clock's frame this one shows (held during a photo's pause), and the photo over it.
  const scene::FilmFrame shown = setup_.frames.empty() ? scene::FilmFrame{next_, std::nullopt} : setup_.frames[next_];
  const std::size_t i = shown.clock_frame, frames = setup_.cameras.size();
  const scene::Lens& lens = setup_.cameras[i].lens();
  const double time = setup_.clock.timing.time_of(i);
  film_.set_time(time);
  scene_.tracks = &film_.tracks();
  scene_.waypoints = &film_.waypoints();
  std::vector<scene::GaugeReadings> gauges;
  for (std::size_t k : setup_.gauged)
    gauges.push_back(scene::gauge_readings((*setup_.tracks)[k], film_.positions()[k]));
  scene_.label_keep_out =
      scene::film_overlay_panels(lens.width_px, lens.height_px, text_, setup_.overlay, gauges, setup_.attribution);
  if (!profile_.altitude_m.empty())
    scene_.label_keep_out.push_back(scene::film_profile_panel(lens.width_px, lens.height_px));
  setup_.terrain->set_policy(setup_.tiles);  // a window's checks in between do not wait
  prefetch_tiles(*setup_.terrain, setup_.cameras[std::min(frames - 1, i + kPrefetchFrames)], scene_.neutral_ground_m);
  renderer.draw(scene_, setup_.cameras[i], picture_);
  scene::draw_scene_legend(picture_.image, legend_scene_);
  scene::draw_film_overlay(picture_.image, text_, setup_.overlay, time, gauges, setup_.attribution);
  if (!setup_.gauged.empty())
    scene::draw_film_profile(picture_.image, profile_, time + setup_.clock.offsets[setup_.gauged.front()]);
  if (shown.photo && setup_.photos[*shown.photo].image)
    scene::draw_film_photo(picture_.image, text_, setup_.photos[*shown.photo].image->pixels,
                           setup_.photos[*shown.photo].caption);
  writer_->add(picture_.image);
  ++next_;
  elapsed_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - *started_).count();
}

FilmProgress FilmRecorder::progress() const {
  FilmProgress p;
  p.done = next_;
  p.total = setup_.frame_count();
  if (next_ > 0) {
    p.frames_per_s = static_cast<double>(next_) / std::max(elapsed_s_, 1e-9);
    p.seconds_left = static_cast<double>(p.total - p.done) / p.frames_per_s;
  }
  return p;
}

void FilmRecorder::finish() {
  if (!done()) throw std::logic_error("the film is not finished");
  if (writer_ == nullptr) throw std::logic_error("the film was cancelled");
  writer_->finish();
}

void FilmRecorder::cancel() { writer_.reset(); }

}  // namespace trailray::app
