// Every GL call the viewer makes itself goes through this table, filled from the current
// context's own GetProcAddress (glfwGetProcAddress or OSMesaGetProcAddress).
//
// Why: libOSMesa and libGL both export the gl* entry points, and a direct call binds to one of
// them whatever context is current. The viewer therefore never calls a gl* symbol directly:
// pathway links no GL library at all (GLFW dlopens libGL for its window, ImGui's OpenGL3 backend
// loads its functions through its own dlopen loader, libOSMesa is opened by the offscreen viewer:
// osmesa_library.h), and what the viewer draws itself uses function pointers from the context it
// draws into. The only direct gl* calls in the program are those of ImGui's OpenGL2 backend, used
// only with OSMesa; gl_legacy_entry_points.cpp forwards them to libOSMesa.
#pragma once

#include <GL/gl.h>  // types and enums only

namespace pathway {

struct GlFunctions {
  using Proc = void (*)();
  using Loader = Proc (*)(const char* name);

  // Throws PathwayError naming the first function the context does not provide.
  void load(Loader loader);

  void (*GenTextures)(GLsizei, GLuint*) = nullptr;
  void (*DeleteTextures)(GLsizei, const GLuint*) = nullptr;
  void (*BindTexture)(GLenum, GLuint) = nullptr;
  void (*TexParameteri)(GLenum, GLenum, GLint) = nullptr;
  void (*TexImage2D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum,
                     const void*) = nullptr;
  void (*TexSubImage2D)(GLenum, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                        const void*) = nullptr;
  void (*PixelStorei)(GLenum, GLint) = nullptr;
  void (*Viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
  void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
  void (*Clear)(GLbitfield) = nullptr;
  void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*) = nullptr;
  void (*Finish)() = nullptr;
  const GLubyte* (*GetString)(GLenum) = nullptr;
};

}  // namespace pathway
