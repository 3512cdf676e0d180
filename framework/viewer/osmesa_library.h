// libOSMesa, opened the first time the offscreen viewer (`pathway view --headless` or
// `--benchmark`) needs it rather than linked.
//
// Why: libOSMesa depends on libLLVM (its llvmpipe rasteriser), and a program linked with it
// relocated LLVM's symbols at every start: 15-20 ms of every `pathway` process, a render's or
// `--help`'s alike.
#pragma once

#include <GL/osmesa.h>  // types and enums only

namespace pathway {

struct OsmesaLibrary {
  decltype(&OSMesaCreateContextExt) createContextExt = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

// Opens the library once (thread-safe) and returns its functions. Throws PathwayError naming the
// library file when it cannot be opened or lacks one of them.
const OsmesaLibrary& osmesaLibrary();

// Any function of the library by name, such as its own glEnable (not the program's, which
// forwards to it: gl_legacy_entry_points.cpp). Throws as osmesaLibrary() does.
void* osmesaSymbol(const char* name);

}  // namespace pathway
