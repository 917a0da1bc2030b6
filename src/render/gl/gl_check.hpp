#pragma once
// Turning GL's error codes into messages: GL reports failures through glGetError and status
// enums, which say nothing to a reader unless named.

#include <string>
#include <string_view>

#include "render/gl/gl_api.hpp"

namespace trailray::render {

// "GL_INVALID_OPERATION", or "GL error 0x1234" for a code this table does not know.
std::string gl_error_name(GLenum error);

// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (an attachment is not renderable or has no storage)".
std::string framebuffer_status_text(GLenum status);

// "GL_RGBA8", or "format 0x1234"; for messages about textures and renderbuffers.
std::string gl_format_name(GLenum internal_format);

// Drains GL's error flags; throws RenderError("GL_INVALID_VALUE after <what>") when any was set.
// GL keeps errors until asked, so call it right after the calls `what` describes.
void check_gl_error(std::string_view what);

}  // namespace trailray::render
