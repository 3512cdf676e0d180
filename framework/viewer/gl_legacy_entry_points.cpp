// The OpenGL 1.x functions ImGui's OpenGL2 backend calls by name (Debian's libimgui.a holds the
// backend compiled, so its calls cannot be redirected), defined here and forwarded to libOSMesa's
// own, which osmesa_library.cpp opens only when the offscreen viewer starts. Linking libOSMesa
// instead would load libLLVM into every `pathway` process (osmesa_library.h).
//
// Only the offscreen viewer calls these: the windowed viewer draws through ImGui's OpenGL3 backend
// and the viewer's own GL calls go through GlFunctions (gl_functions.h), both from the window's
// context. The list is what `nm -u pathway` showed when libOSMesa was linked; a function missing
// here fails the link, and a definition whose parameters differ from GL/gl.h fails to compile.
#include <GL/gl.h>

#include "viewer/osmesa_library.h"

// Each looks its OSMesa function up on its first call.
#define PATHWAY_FORWARD_GL(name, params, args)                                                    \
  extern "C" void name params {                                                                   \
    static const auto osmesa = reinterpret_cast<decltype(&::name)>(pathway::osmesaSymbol(#name)); \
    osmesa args;                                                                                  \
  }

PATHWAY_FORWARD_GL(glBindTexture, (GLenum target, GLuint texture), (target, texture))
PATHWAY_FORWARD_GL(glBlendFunc, (GLenum source, GLenum destination), (source, destination))
PATHWAY_FORWARD_GL(glColorPointer, (GLint size, GLenum type, GLsizei stride, const GLvoid* pointer),
                   (size, type, stride, pointer))
PATHWAY_FORWARD_GL(glDeleteTextures, (GLsizei n, const GLuint* textures), (n, textures))
PATHWAY_FORWARD_GL(glDisable, (GLenum capability), (capability))
PATHWAY_FORWARD_GL(glDisableClientState, (GLenum capability), (capability))
PATHWAY_FORWARD_GL(glDrawElements, (GLenum mode, GLsizei count, GLenum type, const GLvoid* indices),
                   (mode, count, type, indices))
PATHWAY_FORWARD_GL(glEnable, (GLenum capability), (capability))
PATHWAY_FORWARD_GL(glEnableClientState, (GLenum capability), (capability))
PATHWAY_FORWARD_GL(glGenTextures, (GLsizei n, GLuint* textures), (n, textures))
PATHWAY_FORWARD_GL(glGetIntegerv, (GLenum name, GLint* values), (name, values))
PATHWAY_FORWARD_GL(glGetTexEnviv, (GLenum target, GLenum name, GLint* values),
                   (target, name, values))
PATHWAY_FORWARD_GL(glLoadIdentity, (), ())
PATHWAY_FORWARD_GL(glMatrixMode, (GLenum mode), (mode))
PATHWAY_FORWARD_GL(glOrtho,
                   (GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble near,
                    GLdouble far),
                   (left, right, bottom, top, near, far))
PATHWAY_FORWARD_GL(glPixelStorei, (GLenum name, GLint value), (name, value))
PATHWAY_FORWARD_GL(glPolygonMode, (GLenum face, GLenum mode), (face, mode))
PATHWAY_FORWARD_GL(glPopAttrib, (), ())
PATHWAY_FORWARD_GL(glPopMatrix, (), ())
PATHWAY_FORWARD_GL(glPushAttrib, (GLbitfield mask), (mask))
PATHWAY_FORWARD_GL(glPushMatrix, (), ())
PATHWAY_FORWARD_GL(glScissor, (GLint x, GLint y, GLsizei width, GLsizei height),
                   (x, y, width, height))
PATHWAY_FORWARD_GL(glShadeModel, (GLenum mode), (mode))
PATHWAY_FORWARD_GL(glTexCoordPointer,
                   (GLint size, GLenum type, GLsizei stride, const GLvoid* pointer),
                   (size, type, stride, pointer))
PATHWAY_FORWARD_GL(glTexEnvi, (GLenum target, GLenum name, GLint value), (target, name, value))
PATHWAY_FORWARD_GL(glTexImage2D,
                   (GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
                    GLint border, GLenum format, GLenum type, const GLvoid* pixels),
                   (target, level, internalFormat, width, height, border, format, type, pixels))
PATHWAY_FORWARD_GL(glTexParameteri, (GLenum target, GLenum name, GLint value),
                   (target, name, value))
PATHWAY_FORWARD_GL(glVertexPointer,
                   (GLint size, GLenum type, GLsizei stride, const GLvoid* pointer),
                   (size, type, stride, pointer))
PATHWAY_FORWARD_GL(glViewport, (GLint x, GLint y, GLsizei width, GLsizei height),
                   (x, y, width, height))
