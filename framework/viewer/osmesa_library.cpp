#include "viewer/osmesa_library.h"

#include <dlfcn.h>

#include <string>
#include <type_traits>

#include "core/error.h"

namespace pathway {
namespace {

OsmesaLibrary openOsmesa() {
  // RTLD_LOCAL: its gl* symbols stay out of the global scope; ours forward to them
  // (gl_legacy_entry_points.cpp).
  OsmesaLibrary library;
  library.handle = dlopen(PATHWAY_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (!library.handle)
    throw PathwayError(std::string("offscreen viewer: cannot open OSMesa: ") + dlerror());
  auto get = [&](auto& function, const char* name) {
    function =
        reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(library.handle, name));
    if (!function) throw PathwayError(std::string(PATHWAY_OSMESA_LIBRARY) + " has no " + name);
  };
  get(library.createContextExt, "OSMesaCreateContextExt");
  get(library.makeCurrent, "OSMesaMakeCurrent");
  get(library.destroyContext, "OSMesaDestroyContext");
  get(library.getProcAddress, "OSMesaGetProcAddress");
  return library;
}

}  // namespace

const OsmesaLibrary& osmesaLibrary() {
  static const OsmesaLibrary library = openOsmesa();  // a failed open throws, and retries next call
  return library;
}

}  // namespace pathway
