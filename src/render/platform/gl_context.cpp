#include "render/platform/gl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <utility>

#include "render/gl/gl_api.hpp"

namespace trailray::render {
namespace {

std::string egl_error_name(EGLint error) {
  switch (error) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default: {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "EGL error 0x%04X", static_cast<unsigned>(error));
      return buffer;
    }
  }
}

std::string egl_failure(std::string_view call) {
  return std::string(call) + " failed (" + egl_error_name(eglGetError()) + ")";
}

bool has_word(const char* list, std::string_view word) {
  if (!list) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const std::size_t space = rest.find(' ');
    if (rest.substr(0, space) == word) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

// Displays are never terminated (eglTerminate). EGL hands every caller of eglGetPlatformDisplay
// the same display and has no reference count on it: terminating it would end it for every other
// context of the process (tests and the viewer hold several). And terminating makes Mesa unload
// its driver, whose teardown leaks memory LeakSanitizer can then not even attribute. A display
// stays initialized until the process exits, as in most EGL programs; initializing it again is a
// no-op, so creating contexts over and over costs nothing more.

// One way to a display: which platform, which native handle, and how to name it in messages.
struct DisplayCandidate {
  EglPlatform platform;
  EGLenum egl_platform;
  void* native_display;
  std::string name;
};

// Extension entry points: EGL may not export them, so they are looked up by name.
struct EglExtensions {
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  bool platform_device = false, platform_surfaceless = false;

  EglExtensions() {
    // Client extensions (EGL_EXT_client_extensions): NULL where the library predates them.
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (has_word(client, "EGL_EXT_platform_base"))
      get_platform_display =
          reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (has_word(client, "EGL_EXT_device_enumeration") || has_word(client, "EGL_EXT_device_base")) {
      query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
      query_device_string =
          reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    }
    platform_device = get_platform_display && query_devices && has_word(client, "EGL_EXT_platform_device");
    platform_surfaceless = get_platform_display && has_word(client, "EGL_MESA_platform_surfaceless");
  }
};

// The device platform's candidates, GPUs first (in EGL's order), then software devices.
void add_device_candidates(const EglExtensions& egl, std::vector<DisplayCandidate>& gpus,
                           std::vector<DisplayCandidate>& software, std::vector<std::string>& failures) {
  if (!egl.platform_device) {
    failures.push_back("EGL devices: not offered by this EGL (no EGL_EXT_platform_device)");
    return;
  }
  EGLint count = 0;
  if (!egl.query_devices(0, nullptr, &count) || count <= 0) {
    failures.push_back("EGL devices: none found");
    return;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!egl.query_devices(count, devices.data(), &count)) {
    failures.push_back("EGL devices: " + egl_failure("eglQueryDevicesEXT"));
    return;
  }
  devices.resize(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const char* extensions = egl.query_device_string(devices[i], EGL_EXTENSIONS);
    const bool is_software = has_word(extensions, "EGL_MESA_device_software");
    std::string name = "EGL device " + std::to_string(i);
    const char* node = nullptr;
    if (has_word(extensions, "EGL_EXT_device_drm_render_node"))
      node = egl.query_device_string(devices[i], EGL_DRM_RENDER_NODE_FILE_EXT);
    if (!node && has_word(extensions, "EGL_EXT_device_drm"))
      node = egl.query_device_string(devices[i], EGL_DRM_DEVICE_FILE_EXT);
    if (is_software)
      name += " (software)";
    else if (node)
      name += " (" + std::string(node) + ")";
    (is_software ? software : gpus)
        .push_back({EglPlatform::device, EGL_PLATFORM_DEVICE_EXT, static_cast<void*>(devices[i]), std::move(name)});
  }
}

}  // namespace

std::string_view to_string(EglPlatform platform) { return platform == EglPlatform::device ? "device" : "surfaceless"; }

struct GlContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer, only where surfaceless contexts are not offered
  EglPlatform platform = EglPlatform::surfaceless;
  std::string egl_description;
  GlCapabilities capabilities;

  std::string open(const EglExtensions& egl, const DisplayCandidate& candidate, const HeadlessContextOptions& options);
  // Undoes whatever of the set-up was done; safe at any stage.
  void destroy() noexcept {
    if (display == EGL_NO_DISPLAY) return;
    if (context != EGL_NO_CONTEXT && eglGetCurrentContext() == context)
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    display = EGL_NO_DISPLAY;
    context = EGL_NO_CONTEXT;
    surface = EGL_NO_SURFACE;
    // Per-thread EGL state; only released when this thread has no other context current.
    if (eglGetCurrentContext() == EGL_NO_CONTEXT) eglReleaseThread();
  }
};

// Sets up a context on one display; on failure, cleans up and returns why (empty on success).
std::string GlContext::State::open(const EglExtensions& egl, const DisplayCandidate& candidate,
                                   const HeadlessContextOptions& options) {
  State& state = *this;
  const EGLDisplay candidate_display =
      egl.get_platform_display(candidate.egl_platform, candidate.native_display, nullptr);
  if (candidate_display == EGL_NO_DISPLAY) return egl_failure("eglGetPlatformDisplayEXT");
  EGLint egl_major = 0, egl_minor = 0;
  if (!eglInitialize(candidate_display, &egl_major, &egl_minor)) return egl_failure("eglInitialize");
  state.display = candidate_display;
  state.platform = candidate.platform;
  auto fail = [&state](const std::string& why) {
    state.destroy();
    return why;
  };

  if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail(egl_failure("eglBindAPI(EGL_OPENGL_ES_API)"));
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  const bool surfaceless = has_word(extensions, "EGL_KHR_surfaceless_context");
  const bool configless = surfaceless && (has_word(extensions, "EGL_KHR_no_config_context") ||
                                          has_word(extensions, "EGL_MESA_configless_context"));
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!configless) {
    // SURFACE_TYPE 0 would match any config; a pbuffer is what we fall back to without
    // surfaceless contexts.
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE,
                                 surfaceless ? 0 : EGL_PBUFFER_BIT, EGL_NONE};
    EGLint found = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &found)) return fail(egl_failure("eglChooseConfig"));
    if (found < 1) return fail("no EGL config renders OpenGL ES 3");
  }
  if (!surfaceless) {
    const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    state.surface = eglCreatePbufferSurface(display, config, size);
    if (state.surface == EGL_NO_SURFACE) return fail(egl_failure("eglCreatePbufferSurface"));
  }

  // EGL 1.5 and EGL_KHR_create_context know minor versions; older EGL only the major one.
  const bool minor_known = egl_major > 1 || egl_minor >= 5 || has_word(extensions, "EGL_KHR_create_context");
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, options.gles_major,
                                       minor_known ? EGL_CONTEXT_MINOR_VERSION : EGL_NONE, options.gles_minor,
                                       EGL_NONE};
  state.context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (state.context == EGL_NO_CONTEXT) return fail(egl_failure("eglCreateContext"));
  if (!eglMakeCurrent(display, state.surface, state.surface, state.context)) return fail(egl_failure("eglMakeCurrent"));

  state.capabilities = query_gl_capabilities();
  const GlCapabilities& caps = state.capabilities;
  const bool new_enough = caps.major_version > options.gles_major ||
                          (caps.major_version == options.gles_major && caps.minor_version >= options.gles_minor);
  if (!new_enough)
    return fail("the context is \"" + caps.version + "\", not OpenGL ES " + std::to_string(options.gles_major) + "." +
                std::to_string(options.gles_minor) + " or newer");

  const char* vendor = eglQueryString(display, EGL_VENDOR);
  state.egl_description = "EGL " + std::to_string(egl_major) + "." + std::to_string(egl_minor) + " (" +
                          (vendor ? vendor : "unknown vendor") + "), " + std::string(to_string(candidate.platform)) +
                          " platform";
  if (candidate.platform == EglPlatform::device) state.egl_description += ", " + candidate.name;
  return {};
}

GlContext GlContext::create_headless(const HeadlessContextOptions& options) {
  const EglExtensions egl;
  std::vector<DisplayCandidate> gpus, software, candidates;
  std::vector<std::string> failures;
  const bool want_device = !options.platform || *options.platform == EglPlatform::device;
  const bool want_surfaceless = !options.platform || *options.platform == EglPlatform::surfaceless;
  if (want_device) add_device_candidates(egl, gpus, software, failures);
  candidates = gpus;
  if (want_surfaceless) {
    if (egl.platform_surfaceless)
      candidates.push_back(
          {EglPlatform::surfaceless, EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "Mesa surfaceless"});
    else
      failures.push_back("Mesa surfaceless: not offered by this EGL (no EGL_MESA_platform_surfaceless)");
  }
  candidates.insert(candidates.end(), software.begin(), software.end());

  for (const DisplayCandidate& candidate : candidates) {
    auto state = std::make_unique<State>();
    const std::string failure = state->open(egl, candidate, options);
    if (failure.empty()) return GlContext(std::move(state));
    failures.push_back(candidate.name + ": " + failure);
  }
  std::string message = "no OpenGL ES " + std::to_string(options.gles_major) + "." +
                        std::to_string(options.gles_minor) + " context through EGL";
  if (options.platform) message += " (" + std::string(to_string(*options.platform)) + " platform only)";
  message += ": tried ";
  for (std::size_t i = 0; i < failures.size(); ++i) message += (i ? "; " : "") + failures[i];
  if (failures.empty()) message += "nothing: this EGL offers no headless platform";
  throw RenderError(message +
                    ". Headless rendering needs an EGL driver with OpenGL ES 3: Mesa (libegl-mesa0, libgl1-mesa-dri) "
                    "or a GPU vendor's.");
}

GlContext::GlContext(std::unique_ptr<State> state) : state_(std::move(state)) {}
GlContext::GlContext(GlContext&& other) noexcept = default;
GlContext& GlContext::operator=(GlContext&& other) noexcept {
  if (this != &other) {
    release();
    state_ = std::move(other.state_);
  }
  return *this;
}
GlContext::~GlContext() { release(); }

void GlContext::release() noexcept {
  if (state_) state_->destroy();
  state_.reset();
}

const GlContext::State& GlContext::state() const {
  if (!state_) throw RenderError("this GL context was moved from: it holds no context any more");
  return *state_;
}

void GlContext::make_current() const {
  const State& current = state();
  if (!eglMakeCurrent(current.display, current.surface, current.surface, current.context))
    throw RenderError("cannot make the GL context current: " + egl_failure("eglMakeCurrent"));
}

bool GlContext::is_current() const { return state_ && eglGetCurrentContext() == state_->context; }
EglPlatform GlContext::platform() const { return state().platform; }
const std::string& GlContext::egl_description() const { return state().egl_description; }
const GlCapabilities& GlContext::capabilities() const { return state().capabilities; }

std::vector<std::string> GlContext::describe() const {
  std::vector<std::string> lines{egl_description()};
  for (std::string& line : state().capabilities.describe()) lines.push_back(std::move(line));
  return lines;
}

}  // namespace trailray::render
