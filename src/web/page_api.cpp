// The functions the page's JavaScript calls (page/app.js, through cwrap): one viewer per page,
// drawing into the WebGL 2 context of the canvas `#canvas`. Strings returned stay valid until the
// next call of the same function. Every exception stops here, as text for the page to show.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <memory>
#include <string>

#include "web/page_viewer.hpp"

namespace {

std::unique_ptr<trailray::web::PageViewer> viewer;

const char* kept(std::string text) {
  static std::string last;
  last = std::move(text);
  return last.c_str();
}

}  // namespace

extern "C" {

// Makes the WebGL 2 context and the viewer: "" or why the page cannot draw.
EMSCRIPTEN_KEEPALIVE const char* trailray_start() {
  try {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = false;
    attributes.depth = false;  // the frame is composed in the renderer's own targets and copied
    attributes.stencil = false;
    attributes.antialias = false;
    attributes.preserveDrawingBuffer = true;  // the screenshot button and the tests read the canvas
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context("#canvas", &attributes);
    if (context <= 0) return kept("this browser offers no WebGL 2 (the page needs it)");
    emscripten_webgl_make_context_current(context);
    // Float render targets for the G-buffer; the renderer chooses another path without them.
    emscripten_webgl_enable_extension(context, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(context, "OES_texture_float_linear");
    viewer = std::make_unique<trailray::web::PageViewer>();
    return kept("");
  } catch (const std::exception& e) {
    return kept(std::string("the renderer could not start: ") + e.what());
  }
}

EMSCRIPTEN_KEEPALIVE const char* trailray_open_track(const char* name, const char* bytes, int length) {
  if (!viewer) return kept("not started");
  return kept(viewer->open_track(name, std::string_view(bytes, static_cast<std::size_t>(length))));
}

EMSCRIPTEN_KEEPALIVE const char* trailray_set_option(const char* name, const char* value) {
  if (!viewer) return kept("not started");
  return kept(viewer->set_option(name, value));
}

// serve's photos and places (the JSON of its /api/config.json), and a photo's picture as it
// arrives (`large` 1: the larger one, asked for in trailray_status()'s "photos"."wanted").
EMSCRIPTEN_KEEPALIVE const char* trailray_set_served_pins(const char* json) {
  if (!viewer) return kept("not started");
  return kept(viewer->set_served_pins(json));
}
EMSCRIPTEN_KEEPALIVE const char* trailray_photo_picture(int index, int large, const char* bytes, int length) {
  if (!viewer) return kept("not started");
  return kept(viewer->set_photo_picture(index, large != 0, std::string_view(bytes, static_cast<std::size_t>(length))));
}

EMSCRIPTEN_KEEPALIVE void trailray_orbit(double dx, double dy) {
  if (viewer) viewer->orbit(dx, dy);
}
EMSCRIPTEN_KEEPALIVE void trailray_pan(double x0, double y0, double x1, double y1) {
  if (viewer) viewer->pan(x0, y0, x1, y1);
}
EMSCRIPTEN_KEEPALIVE void trailray_zoom(double steps, double x, double y) {
  if (viewer) viewer->zoom(steps, x, y);
}

// The pointer (CSS pixels of the canvas, x NaN: it left; the DOM's button mask), the wheel (lines)
// and keys (the DOM's keyCode; modifier bits 1 ctrl, 2 shift, 4 alt, 8 meta) for the panels. Each
// returns whether the panels want the pointer / the keyboard (as of the last frame): then the
// page does not move the camera with them.
EMSCRIPTEN_KEEPALIVE int trailray_pointer(double x, double y, int buttons) {
  if (!viewer) return 0;
  viewer->input().pointer(x, y, buttons);
  return viewer->wants_mouse() ? 1 : 0;
}
EMSCRIPTEN_KEEPALIVE int trailray_wheel(double steps_y, double steps_x) {
  if (!viewer) return 0;
  const bool wanted = viewer->wants_mouse();
  if (wanted) viewer->input().wheel(steps_y, steps_x);
  return wanted ? 1 : 0;
}
EMSCRIPTEN_KEEPALIVE int trailray_key(int key_code, int down, int modifiers) {
  if (!viewer) return 0;
  viewer->input().key(key_code, down != 0, modifiers & 1, modifiers & 2, modifiers & 4, modifiers & 8);
  return viewer->wants_keyboard() ? 1 : 0;
}
EMSCRIPTEN_KEEPALIVE void trailray_char(int codepoint) {
  if (viewer && codepoint > 0) viewer->input().character(static_cast<unsigned>(codepoint));
}

// The scene's picture alone in the canvas, for the screenshot (read it before the next frame):
// 1, or 0 before the first frame.
EMSCRIPTEN_KEEPALIVE int trailray_picture() { return viewer && viewer->draw_picture() ? 1 : 0; }

// 1 when a frame was drawn, 0 when nothing changed; an error ends as text in trailray_error().
static std::string frame_error;
EMSCRIPTEN_KEEPALIVE int trailray_frame(int width, int height, double pixel_ratio, double seconds) {
  if (!viewer || width <= 0 || height <= 0) return 0;
  try {
    return viewer->frame(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), pixel_ratio, seconds)
               ? 1
               : 0;
  } catch (const std::exception& e) {
    frame_error = e.what();
    return -1;
  }
}
EMSCRIPTEN_KEEPALIVE const char* trailray_error() { return frame_error.c_str(); }

// The legend's pixels (RGBA, straight alpha; its place and size are in trailray_status()).
EMSCRIPTEN_KEEPALIVE const std::uint8_t* trailray_legend_pixels() {
  return viewer && !viewer->legend().rgba.empty() ? viewer->legend().rgba.data() : nullptr;
}

// A script of the desktop's `view --script` commands run on the viewer (PageViewer::run_script):
// {"output", "error"} as JSON. The same script run by `trailray view --script` prints the same
// (print-state, print-hover, print-camera, ...): the browser tests compare them.
EMSCRIPTEN_KEEPALIVE const char* trailray_run_script(const char* text) {
  return kept(viewer ? viewer->run_script(text) : R"({"output":"","error":"not started"})");
}

EMSCRIPTEN_KEEPALIVE const char* trailray_view_state() { return kept(viewer ? viewer->view_state() : ""); }
EMSCRIPTEN_KEEPALIVE const char* trailray_status() { return kept(viewer ? viewer->status_json() : "{}"); }

}  // extern "C"
