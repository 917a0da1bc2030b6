#pragma once
// Named groups of GL commands (KHR_debug): each pass of a frame runs inside one, so a GL
// debugger or driver trace (RenderDoc, apitrace, Mesa's GALLIUM_TRACE) shows the frame as its
// list of passes. The entry points are looked up once (eglGetProcAddress) when the context has
// KHR_debug (GlCapabilities::debug_output); without it a group is a no-op.

#include <string_view>

#include "render/gl/gl_capabilities.hpp"

namespace trailray::render {

class DebugGroups {
 public:
  DebugGroups() = default;  // no groups
  explicit DebugGroups(const GlCapabilities& capabilities);

  bool enabled() const { return push_ != nullptr && pop_ != nullptr; }
  void push(std::string_view name) const;
  void pop() const;

 private:
  // glPushDebugGroupKHR(source, id, length, message) and glPopDebugGroupKHR(), spelled without
  // the GL headers' typedefs (a window's headers may come first and define others).
  using PushFunction = void (*)(unsigned source, unsigned id, int length, const char* message);
  using PopFunction = void (*)();
  PushFunction push_ = nullptr;
  PopFunction pop_ = nullptr;
};

// A group for the lifetime of the scope.
class DebugGroup {
 public:
  DebugGroup(const DebugGroups& groups, std::string_view name) : groups_(groups) { groups_.push(name); }
  ~DebugGroup() { groups_.pop(); }
  DebugGroup(const DebugGroup&) = delete;
  DebugGroup& operator=(const DebugGroup&) = delete;

 private:
  const DebugGroups& groups_;
};

}  // namespace trailray::render
