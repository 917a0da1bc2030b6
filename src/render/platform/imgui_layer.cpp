#include "render/platform/imgui_layer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cfloat>
#include <cmath>

#include "scene/text/embedded_fonts.hpp"

namespace trailray::render {

ImGuiLayer::ImGuiLayer(Window& window, float font_px) : window_(&window) {
  create_context(font_px);
  if (!ImGui_ImplGlfw_InitForOpenGL(window.handle(), true)) {
    ImGui::DestroyContext();
    throw RenderError("ImGui: the GLFW backend did not start");
  }
  if (!ImGui_ImplOpenGL3_Init("#version 300 es")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw RenderError("ImGui: the OpenGL ES 3 backend did not start");
  }
}

ImGuiLayer::ImGuiLayer(float font_px) {
  create_context(font_px);
  if (!ImGui_ImplOpenGL3_Init("#version 300 es")) {
    ImGui::DestroyContext();
    throw RenderError("ImGui: the OpenGL ES 3 backend did not start");
  }
}

void ImGuiLayer::create_context(float font_px) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written into the user's working folder
  ImGui::StyleColorsDark();
  // The font lives in the binary: the atlas must not free it.
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;
  const auto font = scene::detail::dejavu_sans_font();
  // Latin (track names such as "Zürich", "Škofja Loka"), Greek, Cyrillic, and the punctuation and
  // symbols the panels print (the em dash of a missing value, arrows, the degree sign).
  static constexpr ImWchar kRanges[] = {0x0020, 0x024F, 0x0370, 0x03FF, 0x0400, 0x04FF, 0x2000,
                                        0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(font.data()), static_cast<int>(font.size()), font_px,
                                 &config, kRanges);
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  if (window_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::begin_frame(std::optional<std::array<float, 2>> scripted_cursor) {
  ImGui_ImplOpenGL3_NewFrame();
  if (window_) ImGui_ImplGlfw_NewFrame();
  if (scripted_cursor) {
    // Scripts must not depend on where the display's pointer happens to be (Xvfb's starts at the
    // screen's centre, which can lie over a panel).
    ImGuiIO& io = ImGui::GetIO();
    const bool nowhere = std::isnan((*scripted_cursor)[0]);
    io.MousePos = nowhere ? ImVec2(-FLT_MAX, -FLT_MAX) : ImVec2((*scripted_cursor)[0], (*scripted_cursor)[1]);
    for (bool& down : io.MouseDown) down = false;
    io.MouseWheel = io.MouseWheelH = 0.0f;
  }
  ImGui::NewFrame();
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace trailray::render
