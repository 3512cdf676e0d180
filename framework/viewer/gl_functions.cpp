#include "viewer/gl_functions.h"

#include <string>
#include <type_traits>

#include "core/error.h"

namespace pathway {

void GlFunctions::load(Loader loader) {
  auto get = [loader](auto& function, const char* name) {
    function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(loader(name));
    if (!function) throw PathwayError(std::string("the OpenGL context has no ") + name);
  };
  get(GenTextures, "glGenTextures");
  get(DeleteTextures, "glDeleteTextures");
  get(BindTexture, "glBindTexture");
  get(TexParameteri, "glTexParameteri");
  get(TexImage2D, "glTexImage2D");
  get(TexSubImage2D, "glTexSubImage2D");
  get(PixelStorei, "glPixelStorei");
  get(Viewport, "glViewport");
  get(ClearColor, "glClearColor");
  get(Clear, "glClear");
  get(ReadPixels, "glReadPixels");
  get(Finish, "glFinish");
  get(GetString, "glGetString");
}

}  // namespace pathway
