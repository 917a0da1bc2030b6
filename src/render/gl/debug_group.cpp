#include "render/gl/debug_group.hpp"

#include <EGL/egl.h>

#include <algorithm>

#include "render/gl/gl_api.hpp"

namespace trailray::render {
namespace {

// The extension's name, else ES 3.2's core one.
template <class F>
F lookup(const char* extension_name, const char* core_name) {
  if (auto f = reinterpret_cast<F>(eglGetProcAddress(extension_name))) return f;
  return reinterpret_cast<F>(eglGetProcAddress(core_name));
}

}  // namespace

DebugGroups::DebugGroups(const GlCapabilities& capabilities) {
  if (!capabilities.debug_output) return;
  push_ = lookup<PushFunction>("glPushDebugGroupKHR", "glPushDebugGroup");
  pop_ = lookup<PopFunction>("glPopDebugGroupKHR", "glPopDebugGroup");
}

void DebugGroups::push(std::string_view name) const {
  if (!enabled()) return;
  // GL_MAX_DEBUG_MESSAGE_LENGTH is at least 1: pass names are far shorter than any real limit.
  const auto length = static_cast<GLsizei>(std::min<std::size_t>(name.size(), 256));
  static_assert(sizeof(GLenum) == sizeof(unsigned) && sizeof(GLsizei) == sizeof(int));
  push_(GL_DEBUG_SOURCE_APPLICATION_KHR, 0, length, name.data());
}

void DebugGroups::pop() const {
  if (enabled()) pop_();
}

}  // namespace trailray::render
