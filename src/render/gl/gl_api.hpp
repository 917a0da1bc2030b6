#pragma once
// The one place the OpenGL ES headers come in: ES 3.0 core (libGLESv2 exports it) and the
// extension enums (GL_TIME_ELAPSED_EXT, ...). Extension entry points are not called directly:
// they are looked up with eglGetProcAddress when GlCapabilities says they are there.

#include <GLES3/gl3.h>
// gl2ext.h declares the extension tokens for ES 2 and 3 alike.
#include <GLES2/gl2ext.h>
