// Every GL call the viewer makes itself goes through this table, filled from the current
// context's own GetProcAddress (glfwGetProcAddress or OSMesaGetProcAddress).
//
// Why: libOSMesa and libGL both export the gl* entry points, and a program linking both gets one
// of them for every direct call, whatever context is current. The viewer therefore never calls a
// gl* symbol directly: pathway does not link libGL at all (GLFW dlopens it for its window, and
// ImGui's OpenGL3 backend loads its functions through its own dlopen loader), and what the
// viewer draws itself uses function pointers from the context it draws into. The only direct
// gl* calls in the program are those of ImGui's OpenGL2 backend, used only with OSMesa, and they
// resolve to libOSMesa because it is the only GL library linked.
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
