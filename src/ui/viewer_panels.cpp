// The viewer's ImGui windows: track list, statistics, shading, occlusion, profiler, profile chart,
// replay and errors. Each edits the model in place; draw_panels calls the open ones.
#include <fmt/format.h>
#include <imgui.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "scene/volumes/volume_shapes.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "track/density.hpp"
#include "ui/flight_panel.hpp"
#include "ui/panel_layout.hpp"
#include "ui/profile_chart.hpp"
#include "ui/viewer_panels.hpp"

namespace trailray::ui {
namespace {

// A combo over a list of names; returns true when the choice changed.
template <typename Names>
bool name_combo(const char* label, int& index, const Names& names) {
  const std::string current = index >= 0 && index < static_cast<int>(names.size())
                                  ? std::string(names[static_cast<std::size_t>(index)])
                                  : std::string();
  bool changed = false;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const bool selected = static_cast<int>(i) == index;
      if (ImGui::Selectable(std::string(names[i]).c_str(), selected) && !selected) {
        index = static_cast<int>(i);
        changed = true;
      }
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  return changed;
}

std::vector<std::string> track_names(const ViewerModel& model) {
  std::vector<std::string> names;
  for (const scene::Track& t : model.tracks.tracks()) names.push_back(t.name);
  return names;
}

void colour_scale_controls(ViewerModel& model) {
  scene::TrackStyle& s = model.settings.style.tracks;
  int metric = static_cast<int>(s.color_by);
  if (name_combo("colour by", metric, track::color_metric_names())) {
    const track::ColorMetric previous = s.color_by;
    const auto next = static_cast<track::ColorMetric>(metric);
    try {
      apply_color_metric(model.tracks, next, s.neighbour_radius_m, model.parallel_for);
      s.color_by = next;
      s.range.reset();  // another metric's range means nothing for this one
      // Into or out of a metric with a map of its own (phase, density, thermals): it means little
      // for the others.
      if (scene::default_colormap(previous) != scene::default_colormap(s.color_by))
        s.colormap = scene::default_colormap(s.color_by);
    } catch (const std::exception& e) {
      model.errors.push_back(fmt::format("colour by {}: {}", track::color_metric_name(next), e.what()));
      apply_color_metric(model.tracks, previous, s.neighbour_radius_m, model.parallel_for);
    }
  }
  if (s.color_by == track::ColorMetric::solid) return;
  if (track::counts_neighbours(s.color_by)) {
    // Counted again once the slider is let go: a season of tracks takes a moment.
    auto radius = static_cast<float>(scene::neighbour_radius_m(s));
    ImGui::SliderFloat("radius", &radius, 10.0f, 5000.0f, "%.0f m", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemDeactivatedAfterEdit() && radius >= track::kMinNeighbourRadiusM &&
        radius <= track::kMaxNeighbourRadiusM) {
      s.neighbour_radius_m = static_cast<double>(radius);
      apply_color_metric(model.tracks, s.color_by, s.neighbour_radius_m, model.parallel_for);
    }
  }
  static constexpr const char* kColormaps[] = {"turbo", "viridis", "magma", "cividis", "diverging", "warm"};
  int map = static_cast<int>(s.colormap);
  if (name_combo("colormap", map, std::vector<std::string>(std::begin(kColormaps), std::end(kColormaps))))
    s.colormap = static_cast<scene::Colormap>(map);
  bool automatic = !s.range.has_value();
  if (ImGui::Checkbox("automatic range", &automatic)) {
    if (automatic)
      s.range.reset();
    else
      s.range = model.color_range().value_or(track::ValueRange{0.0, 1.0});
  }
  const auto range = model.color_range();
  const std::string unit(track::color_metric_unit(s.color_by));
  if (s.range) {
    double lo = s.range->min, hi = s.range->max;
    ImGui::InputDouble(fmt::format("min {}", unit).c_str(), &lo, 0.0, 0.0, "%.1f");
    ImGui::InputDouble(fmt::format("max {}", unit).c_str(), &hi, 0.0, 0.0, "%.1f");
    if (std::isfinite(lo) && std::isfinite(hi) && lo < hi) s.range = track::ValueRange{lo, hi};
  } else if (range) {
    ImGui::Text("range %s to %s %s", track::format_color_value(s.color_by, range->min).c_str(),
                track::format_color_value(s.color_by, range->max).c_str(), unit.c_str());
  } else {
    ImGui::TextDisabled("no point has a value");
  }
}

void width_controls(scene::TrackStyle& s) {
  float width = static_cast<float>(s.width.value);
  const bool pixels = s.width.unit == scene::TrackWidth::Unit::pixels;
  if (ImGui::SliderFloat("width", &width, pixels ? 1.0f : 0.5f, pixels ? 30.0f : 200.0f, pixels ? "%.1f px" : "%.1f m",
                         ImGuiSliderFlags_Logarithmic) &&
      width > 0.0f)
    s.width.value = width;
  int unit = pixels ? 0 : 1;
  ImGui::SameLine();
  if (ImGui::RadioButton("px", &unit, 0) && !pixels) s.width = {5.0, scene::TrackWidth::Unit::pixels};
  ImGui::SameLine();
  if (ImGui::RadioButton("m", &unit, 1) && pixels) s.width = {10.0, scene::TrackWidth::Unit::metres};
}

// The panels' first placement for the window's size now (later the user's own).
PanelLayout layout_now(const ViewerModel& model) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  return default_panel_layout(display.x, display.y, model.settings.show_menu ? ImGui::GetFrameHeight() : 0.0f);
}

void place_at(const PanelRect& r) {
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_FirstUseEver);
  if (r.collapsed) ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
}

void place(const PanelRect& r) {
  place_at(r);
  ImGui::SetNextWindowSize(ImVec2(r.width, r.height), ImGuiCond_FirstUseEver);
}

// The waypoints of one file (or the places of one --labels file), folded under a line naming
// how many there are (and the file, where no track above names it); a click flies to one.
void waypoint_list(const ViewerModel& model, const std::string& source, scene::WaypointKind kind, bool name_file,
                   PanelActions& actions) {
  std::vector<std::size_t> of_source;
  for (std::size_t w = 0; w < model.waypoints.points.size(); ++w)
    if (model.waypoints.points[w].source == source && model.waypoints.points[w].kind == kind) of_source.push_back(w);
  if (of_source.empty()) return;
  const bool place = kind == scene::WaypointKind::Place;
  const char* what = place ? "place" : kind == scene::WaypointKind::Thermal ? "thermal" : "waypoint";
  std::string title = fmt::format("{} {}{}", of_source.size(), what, of_source.size() == 1 ? "" : "s");
  if (name_file) title += ": " + std::filesystem::path(source).filename().string();
  ImGui::PushID(source.c_str());
  ImGui::PushID(static_cast<int>(kind));
  if (ImGui::TreeNode("##waypoints", "%s", title.c_str())) {
    for (const std::size_t w : of_source) {
      const scene::Waypoint& p = model.waypoints.points[w];
      ImGui::PushID(static_cast<int>(w));
      const std::string label = p.name.empty() ? std::string("(no name)") : p.name;
      if (ImGui::Selectable(label.c_str(), model.hover.waypoint == static_cast<int>(w)))
        actions.fly_to_waypoint = static_cast<int>(w);
      if (ImGui::IsItemHovered() && !p.description.empty()) ImGui::SetTooltip("%s", p.description.c_str());
      ImGui::PopID();
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
  ImGui::PopID();
}

// The photos of --photos, in the order they were taken, under a line saying how many: each
// its file's name and time (UTC); a click flies to it and shows it larger (the shell's fly-to).
void photo_list(const ViewerModel& model, PanelActions& actions) {
  std::vector<std::size_t> photos;
  for (std::size_t w = 0; w < model.waypoints.points.size(); ++w)
    if (model.waypoints.points[w].kind == scene::WaypointKind::Photo) photos.push_back(w);
  if (photos.empty()) return;
  std::stable_sort(photos.begin(), photos.end(), [&](std::size_t a, std::size_t b) {
    return model.waypoints.points[a].time_unix_s < model.waypoints.points[b].time_unix_s;
  });
  ImGui::PushID("photos");
  if (ImGui::TreeNodeEx("##photos", ImGuiTreeNodeFlags_DefaultOpen, "%zu photo%s", photos.size(),
                        photos.size() == 1 ? "" : "s")) {
    for (const std::size_t w : photos) {
      const scene::Waypoint& p = model.waypoints.points[w];
      ImGui::PushID(static_cast<int>(w));
      std::string label = p.name;
      if (std::isfinite(p.time_unix_s)) {
        const auto day = static_cast<long long>(std::floor(p.time_unix_s)) % 86400;
        label += fmt::format("  {:02d}:{:02d}:{:02d} UTC", day / 3600, day / 60 % 60, day % 60);
      }
      if (p.thumbnail == nullptr) label += " (not decoded)";
      if (ImGui::Selectable(label.c_str(), p.enlarged || model.hover.waypoint == static_cast<int>(w)))
        actions.fly_to_waypoint = static_cast<int>(w);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.source.c_str());
      ImGui::PopID();
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
}

bool contains_any_case(std::string_view text, std::string_view part) {
  const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  return std::search(text.begin(), text.end(), part.begin(), part.end(),
                     [&](char a, char b) { return lower(a) == lower(b); }) != text.end();
}

// Above a list of several tracks: show or hide all of them (those the filter lists), and the
// filter itself.
void many_tracks_controls(ViewerModel& model) {
  const auto set_all = [&](bool visible) {
    for (scene::Track& t : model.tracks.tracks())
      if (model.track_filter.empty() || contains_any_case(t.name, model.track_filter)) t.visible = visible;
  };
  if (ImGui::SmallButton("show all")) set_all(true);
  ImGui::SameLine();
  if (ImGui::SmallButton("hide all")) set_all(false);
  ImGui::SameLine();
  char filter[128] = {};
  model.track_filter.copy(filter, sizeof(filter) - 1);
  ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x));
  if (ImGui::InputTextWithHint("##filter", "filter by name", filter, sizeof(filter))) model.track_filter = filter;
}

void track_list_window(ViewerModel& model, PanelActions& actions) {
  place(layout_now(model).tracks);
  if (!ImGui::Begin("Tracks", &model.settings.show_tracks)) {
    ImGui::End();
    return;
  }
  if (model.loading) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "loading terrain...");
  if (model.tracks.empty())
    ImGui::TextDisabled("No track: drop a track file (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON) onto the window.");
  if (model.tracks.size() > 1) many_tracks_controls(model);
  model.track_row_heights.resize(model.tracks.size(), 0.0f);
  // Rows out of sight (heights known from an earlier frame) are only stepped over.
  const float view_top = ImGui::GetScrollY(), view_bottom = view_top + ImGui::GetWindowHeight();
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  for (std::size_t i = 0; i < model.tracks.size(); ++i) {
    scene::Track& t = model.tracks[i];
    if (!model.track_filter.empty() && !contains_any_case(t.name, model.track_filter)) continue;
    const float y = ImGui::GetCursorPosY();
    float& height = model.track_row_heights[i];
    if (height > spacing && (y + height < view_top || y > view_bottom)) {
      ImGui::Dummy(ImVec2(1.0f, height - spacing));
      continue;
    }
    ImGui::PushID(static_cast<int>(i));
    ImGui::Checkbox("##visible", &t.visible);
    ImGui::SameLine();
    ImGui::ColorEdit3("##colour", glm::value_ptr(t.color_srgb), ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    const std::string label = t.is_route ? t.name + " (route)" : t.name;
    if (ImGui::Selectable(label.c_str(), model.selected_track == static_cast<int>(i), 0,
                          ImVec2(std::max(40.0f, ImGui::GetContentRegionAvail().x - 60.0f), 0.0f)))
      model.selected_track = static_cast<int>(i);
    ImGui::SameLine();
    if (ImGui::SmallButton("fly to")) actions.fly_to_track = static_cast<int>(i);
    if (model.settings.style.tracks.color_by != track::ColorMetric::solid && !t.is_route) {
      ImGui::Indent();
      ImGui::Checkbox("by value", &t.by_value);
      ImGui::Unindent();
    }
    ImGui::PopID();
    // After a file's last track: its waypoints.
    if (i + 1 == model.tracks.size() || model.tracks[i + 1].source != t.source) {
      ImGui::Indent();
      waypoint_list(model, t.source, scene::WaypointKind::Waypoint, false, actions);
      waypoint_list(model, t.source, scene::WaypointKind::Thermal, false, actions);
      ImGui::Unindent();
    }
    height = ImGui::GetCursorPosY() - y;
  }
  // Files of waypoints alone, then the places of --labels, each file once.
  std::vector<std::pair<std::string, scene::WaypointKind>> files;
  std::unordered_set<std::string_view> track_sources;
  for (const scene::Track& t : model.tracks.tracks()) track_sources.insert(t.source);
  for (const scene::Waypoint& w : model.waypoints.points) {
    if (w.kind == scene::WaypointKind::Photo) continue;  // listed together below
    const bool under_a_track = w.kind != scene::WaypointKind::Place && track_sources.count(w.source) > 0;
    const std::pair<std::string, scene::WaypointKind> file{w.source, w.kind};
    if (!under_a_track && std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  }
  for (const auto& [file, kind] : files) waypoint_list(model, file, kind, true, actions);
  photo_list(model, actions);
  ImGui::Separator();
  scene::TrackStyle& s = model.settings.style.tracks;
  width_controls(s);
  colour_scale_controls(model);
  ImGui::Checkbox("legend", &model.settings.style.legend);
  if (!model.waypoints.points.empty()) {
    ImGui::SameLine();
    if (ImGui::Checkbox("waypoints", &model.settings.show_waypoints))
      scene::set_waypoints_visible(model.waypoints, model.settings.show_waypoints);
  }
  if (!model.volumes.volumes.empty()) {
    ImGui::SameLine();
    if (ImGui::Checkbox("airspace", &model.settings.show_airspace))
      scene::set_volumes_visible(model.volumes, scene::VolumeKind::Airspace, model.settings.show_airspace);
  }
  ImGui::SameLine();
  ImGui::Checkbox("labels", &model.settings.style.labels.enabled);
  ImGui::SameLine();
  if (ImGui::Checkbox("curtain", &s.curtain)) apply_curtain(model.tracks, s.curtain, model.neutral_ground_m);
  ImGui::End();
}

void statistics_window(ViewerModel& model, PanelActions& actions) {
  place(layout_now(model).statistics);
  if (!ImGui::Begin("Statistics", &model.settings.show_statistics)) {
    ImGui::End();
    return;
  }
  if (model.tracks.empty()) {
    ImGui::TextDisabled("No track.");
  } else {
    int selected = std::clamp(model.selected_track, 0, static_cast<int>(model.tracks.size()) - 1);
    if (name_combo("track", selected, track_names(model))) model.selected_track = selected;
    const scene::Track& t = model.tracks[static_cast<std::size_t>(selected)];
    ImGui::TextDisabled("%s", t.source.c_str());
    for (const std::string& line : statistics_lines(t.summary.clean)) ImGui::TextUnformatted(line.c_str());
    flight_statistics(t, actions);
    if (!model.visit_places.empty()) {  // --places
      const std::vector<std::string> lines =
          places_visited_panel_lines(model.places_visited.of(t, model.visit_places));
      if (lines.empty()) ImGui::TextDisabled("No summit reached, no hut passed.");
      for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
    }
  }
  ImGui::End();
}

void shading_window(ViewerModel& model) {
  place_at(layout_now(model).shading);
  if (!ImGui::Begin("Shading", &model.settings.show_shading, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  ViewerSettings& s = model.settings;
  if (std::isnan(s.sun_time_unix)) {
    // The shell chooses the sun until the user moves it: start the slider from the tracks' time.
    const auto span = common_time_span(model.tracks);
    s.sun_time_unix = span ? span->start
                           : static_cast<double>(std::chrono::duration_cast<std::chrono::seconds>(
                                                     std::chrono::system_clock::now().time_since_epoch())
                                                     .count());
  }
  const double day_start = std::floor(s.sun_time_unix / 86400.0) * 86400.0;
  float hours = static_cast<float>((s.sun_time_unix - day_start) / 3600.0);
  if (ImGui::SliderFloat("time of day (UTC)", &hours, 0.0f, 24.0f, "%.2f h"))
    s.sun_time_unix = day_start + std::clamp(static_cast<double>(hours), 0.0, 24.0 - 1e-6) * 3600.0;
  scene::Shading& shading = s.style.shading;
  ImGui::Checkbox("shadows", &shading.shadows);
  ImGui::Checkbox("ambient occlusion (SSAO)", &shading.ssao);
  ImGui::Checkbox("atmosphere", &shading.atmosphere);
  if (model.offers_moving_frame) ImGui::Checkbox("cheaper frame while moving", &s.moving_frame);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "half resolution, no ambient occlusion, shadows not redrawn; the full frame once the camera rests");
  ImGui::Checkbox("snow", &shading.snow.enabled);
  if (shading.snow.enabled) {
    float snowline = static_cast<float>(shading.snow.snowline_m);
    if (ImGui::SliderFloat("snowline", &snowline, 0.0f, 5000.0f, "%.0f m")) shading.snow.snowline_m = snowline;
  }
  ImGui::End();
}

void occlusion_window(ViewerModel& model) {
  place_at(layout_now(model).occlusion);
  if (!ImGui::Begin("Occlusion", &model.settings.show_occlusion, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  scene::TrackOcclusion& o = model.settings.style.tracks.occlusion;
  ImGui::Checkbox("show hidden parts", &o.enabled);
  ImGui::SliderFloat("alpha", &o.alpha, 0.0f, 1.0f, "%.2f");
  float near_m = o.fade_near_m, far_m = o.fade_far_m;
  ImGui::DragFloat("fade from", &near_m, 5.0f, 0.0f, 100000.0f, "%.0f m");
  ImGui::DragFloat("fade to", &far_m, 5.0f, 0.0f, 100000.0f, "%.0f m");
  // The pass needs NEAR < FAR (as --occlusion-fade does).
  if (near_m >= 0.0f && far_m > near_m) {
    o.fade_near_m = near_m;
    o.fade_far_m = far_m;
  }
  ImGui::End();
}

void profiler_window(ViewerModel& model) {
  place_at(layout_now(model).profiler);
  if (!ImGui::Begin("Profiler", &model.settings.show_profiler, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  const ProfilerTable& p = model.profile;
  ImGui::Text("%.1f FPS (%.2f ms per frame)", p.fps, p.frame_ms);
  constexpr double kMiB = 1024.0 * 1024.0;
  ImGui::Text("GPU terrain: meshes %.0f of %.0f MiB, imagery %.0f of %.0f MiB",
              static_cast<double>(p.mesh_bytes) / kMiB, static_cast<double>(p.mesh_budget_bytes) / kMiB,
              static_cast<double>(p.imagery_bytes) / kMiB, static_cast<double>(p.imagery_budget_bytes) / kMiB);
  if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("CPU ms");
    ImGui::TableSetupColumn("GPU ms");
    ImGui::TableHeadersRow();
    const auto cell = [](const std::optional<double>& ms) {
      ImGui::TableNextColumn();
      if (ms)
        ImGui::Text("%.2f", *ms);
      else
        ImGui::TextDisabled("n/a");
    };
    for (const ProfilerRow& row : p.rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.pass.c_str());
      cell(row.cpu_ms);
      cell(row.gpu_ms);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void chart_window(ViewerModel& model) {
  place(layout_now(model).chart);
  if (ImGui::Begin("Profile", &model.settings.show_chart)) draw_profile_chart(model);
  ImGui::End();
}

std::string clock_text(double unix_s) {
  const auto whole = static_cast<long long>(std::floor(unix_s));
  const long long day_s = ((whole % 86400) + 86400) % 86400;
  return fmt::format("{:02}:{:02}:{:02} UTC", day_s / 3600, (day_s / 60) % 60, day_s % 60);
}

void replay_window(ViewerModel& model, const FilmPanel* film) {
  place(layout_now(model).replay);
  if (!ImGui::Begin("Replay", &model.settings.show_replay)) {
    ImGui::End();
    return;
  }
  ReplayClock& clock = model.clock;
  if (!clock.span()) {
    ImGui::TextDisabled("No track has times.");
    ImGui::End();
    return;
  }
  if (ImGui::Button(clock.playing() ? "pause" : "play")) clock.toggle();
  ImGui::SameLine();
  ImGui::TextUnformatted(clock_text(clock.time()).c_str());
  if (film) {
    ImGui::SameLine();
    film->button(model);
  }
  float speed = static_cast<float>(clock.speed());
  if (ImGui::SliderFloat("speed", &speed, static_cast<float>(ReplayClock::kMinSpeed),
                         static_cast<float>(ReplayClock::kMaxSpeed), "%.0fx", ImGuiSliderFlags_Logarithmic))
    clock.set_speed(speed);
  float fraction = static_cast<float>(clock.fraction());
  if (ImGui::SliderFloat("##scrub", &fraction, 0.0f, 1.0f, "")) clock.seek_fraction(fraction);
  static constexpr const char* kFollow[] = {"off", "chase", "fixed orbit"};
  int follow = static_cast<int>(clock.follow);
  if (name_combo("camera follows", follow, std::vector<std::string>(std::begin(kFollow), std::end(kFollow))))
    clock.follow = static_cast<FollowMode>(follow);
  if (clock.follow != FollowMode::off && !model.tracks.empty()) {
    int t = std::clamp(clock.follow_track, 0, static_cast<int>(model.tracks.size()) - 1);
    if (name_combo("track", t, track_names(model))) clock.follow_track = t;
  }
  ImGui::End();
}

void errors_window(ViewerModel& model) {
  if (model.errors.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 40.0f), ImGuiCond_Appearing, ImVec2(0.5f, 0.0f));
  ImGui::Begin("Errors", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  for (const std::string& e : model.errors) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", e.c_str());
  if (ImGui::Button("dismiss")) model.errors.clear();
  ImGui::End();
}

void window_menu(ViewerSettings& s, bool film) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("Windows")) {
    ImGui::MenuItem("Tracks", nullptr, &s.show_tracks);
    ImGui::MenuItem("Statistics", nullptr, &s.show_statistics);
    ImGui::MenuItem("Profile", nullptr, &s.show_chart);
    ImGui::MenuItem("Replay", nullptr, &s.show_replay);
    if (film) ImGui::MenuItem("Record film", nullptr, &s.show_film);
    ImGui::MenuItem("Shading", nullptr, &s.show_shading);
    ImGui::MenuItem("Occlusion", nullptr, &s.show_occlusion);
    ImGui::MenuItem("Profiler", nullptr, &s.show_profiler);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

}  // namespace

PanelActions draw_panels(ViewerModel& model, double wall_seconds, const FilmPanel* film) {
  PanelActions actions;
  keep_clock_span(model);
  model.clock.advance(wall_seconds);
  ViewerSettings& s = model.settings;
  if (s.show_menu) window_menu(s, film != nullptr);
  if (s.show_tracks) track_list_window(model, actions);
  if (s.show_statistics) statistics_window(model, actions);
  if (s.show_shading) shading_window(model);
  if (s.show_occlusion) occlusion_window(model);
  if (s.show_profiler) profiler_window(model);
  if (s.show_chart) chart_window(model);
  if (s.show_replay) replay_window(model, film);
  if (film && s.show_film) film->window(model, layout_now(model).film, actions);
  errors_window(model);
  return actions;
}

}  // namespace trailray::ui
