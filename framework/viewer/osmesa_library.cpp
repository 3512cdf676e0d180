#include "viewer/osmesa_library.h"

#include <dlfcn.h>

#include <string>
#include <type_traits>

#include "core/error.h"

namespace pathway {
namespace {

// RTLD_LOCAL: the library's gl* symbols stay out of the global scope, where the program's own
// (gl_legacy_entry_points.cpp) are.
void* openedLibrary() {
  static void* const handle = [] {
    void* opened = dlopen(PATHWAY_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!opened) {
      const char* why = dlerror();
      throw PathwayError(std::string("offscreen viewer: cannot open ") + PATHWAY_OSMESA_LIBRARY +
                         ": " + (why ? why : "unknown error"));
    }
    return opened;
  }();  // a failed open throws, and is tried again on the next call
  return handle;
}

OsmesaLibrary loadFunctions() {
  OsmesaLibrary library;
  auto get = [](auto& function, const char* name) {
    function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(osmesaSymbol(name));
  };
  get(library.createContextExt, "OSMesaCreateContextExt");
  get(library.makeCurrent, "OSMesaMakeCurrent");
  get(library.destroyContext, "OSMesaDestroyContext");
  get(library.getProcAddress, "OSMesaGetProcAddress");
  return library;
}

}  // namespace

void* osmesaSymbol(const char* name) {
  void* symbol = dlsym(openedLibrary(), name);
  if (!symbol) throw PathwayError(std::string(PATHWAY_OSMESA_LIBRARY) + " has no " + name);
  return symbol;
}

const OsmesaLibrary& osmesaLibrary() {
  static const OsmesaLibrary library = loadFunctions();
  return library;
}

}  // namespace pathway
