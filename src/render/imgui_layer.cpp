#include "render/imgui_layer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "render/embedded_fonts.hpp"

namespace trailray::render {

ImGuiLayer::ImGuiLayer(Window& window, float font_px) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written into the user's working folder
  ImGui::StyleColorsDark();
  // The font lives in the binary: the atlas must not free it.
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;
  const auto font = detail::dejavu_sans_font();
  io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(font.data()), static_cast<int>(font.size()), font_px,
                                 &config, io.Fonts->GetGlyphRangesDefault());
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

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace trailray::render
