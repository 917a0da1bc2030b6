#include "app/view/film_panel.hpp"
#include "app/view/film_settings.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace trailray::app::view {
namespace {

const ImVec4 kWarning{1.0f, 0.8f, 0.3f, 1.0f};
constexpr float kFieldWidth = 200.0f, kWrapWidth = 300.0f;  // the window's width, about

std::string minutes_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

// The viewer's own choice of track to follow: the replay's, else the statistics panel's.
int viewer_track(const ViewerModel& model) {
  return model.clock.follow != FollowMode::off ? model.clock.follow_track : model.selected_track;
}

void progress_rows(ViewerModel& model, PanelActions& actions) {
  const FilmStatus& f = model.film_status;
  ImGui::TextWrapped("recording %s", f.path.c_str());
  const float fraction = f.total > 0 ? static_cast<float>(f.done) / static_cast<float>(f.total) : 0.0f;
  const std::string frames = fmt::format("{} / {} frames", f.done, f.total);
  ImGui::ProgressBar(fraction, ImVec2(kFieldWidth, 0.0f), frames.c_str());
  if (f.waiting)
    ImGui::TextColored(kWarning, "waiting for terrain tiles...");
  else if (f.done > 0)
    ImGui::Text("%.2f frames/s, %s left", f.frames_per_s, minutes_text(f.seconds_left).c_str());
  else
    ImGui::TextUnformatted("starting...");
  if (ImGui::Button("cancel")) actions.cancel_film = true;
}

void settings_rows(ViewerModel& model, PanelActions& actions) {
  FilmSettings& s = model.film;
  if (s.path.empty()) s.path = default_film_path(model.tracks);
  int camera = static_cast<int>(s.camera);
  if (ImGui::Combo("camera", &camera, kFilmCameraNames, static_cast<int>(std::size(kFilmCameraNames))))
    s.camera = static_cast<FilmCamera>(camera);
  if (s.camera == FilmCamera::follow && !model.tracks.empty()) {
    const std::size_t followed = film_follow_track(s, model.tracks, viewer_track(model));
    if (ImGui::BeginCombo("follows", model.tracks[followed].name.c_str())) {
      for (std::size_t i = 0; i < model.tracks.size(); ++i)
        if (ImGui::Selectable(model.tracks[i].name.c_str(), i == followed)) s.follow_track = static_cast<int>(i);
      ImGui::EndCombo();
    }
  }
  std::array<char, 1024> path{};
  std::strncpy(path.data(), s.path.c_str(), path.size() - 1);
  if (ImGui::InputText("file", path.data(), path.size())) s.path = path.data();
  ImGui::InputDouble("length (s)", &s.seconds, 10.0, 60.0, "%.0f");
  ImGui::InputDouble("frames/s", &s.fps, 1.0, 5.0, "%.0f");
  int size[2] = {s.width, s.height};
  if (ImGui::InputInt2("size (px)", size)) s.width = size[0], s.height = size[1];
  ImGui::Checkbox("replace an existing file", &s.replace);
  const std::string problem = film_settings_problem(s);
  if (!problem.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    ImGui::TextWrapped("%s", problem.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::BeginDisabled(!problem.empty());
  if (ImGui::Button("record film")) actions.record_film = true;
  ImGui::EndDisabled();
  if (!model.film_status.result.empty()) ImGui::TextWrapped("%s", model.film_status.result.c_str());
}

}  // namespace

void film_button(ViewerModel& model) {
  const FilmStatus& f = model.film_status;
  const std::string label =
      f.recording ? fmt::format("film {}/{}###film", f.done, f.total) : std::string("record film...###film");
  if (ImGui::SmallButton(label.c_str())) model.settings.show_film = true;
}

void film_window(ViewerModel& model, const PanelRect& place, PanelActions& actions) {
  // Its right edge on the replay panel's: it grows to the left, into the window.
  ImGui::SetNextWindowPos(ImVec2(place.x, place.y), ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
  if (!ImGui::Begin("Record film", &model.settings.show_film, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(kFieldWidth);
  ImGui::PushTextWrapPos(kWrapWidth);
  if (model.film_status.recording)
    progress_rows(model, actions);
  else
    settings_rows(model, actions);
  ImGui::PopTextWrapPos();
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace trailray::app::view
