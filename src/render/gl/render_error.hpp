#pragma once
// The exception the renderer throws when GL cannot do what is asked: no EGL or no OpenGL ES 3
// context, a shader that does not compile, an incomplete framebuffer, an allocation GL refuses,
// a PNG that cannot be written. The message says what was attempted and why it failed.

#include <stdexcept>

namespace trailray::render {

class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trailray::render
