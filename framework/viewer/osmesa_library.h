// libOSMesa, opened the first time the offscreen viewer needs it rather than linked.
//
// Why: libOSMesa depends on libLLVM (its llvmpipe rasteriser), and a program linked with it
// relocated LLVM's symbols at every start, about 15 ms of every `pathway` process, a render's or
// `--help`'s alike. Only `pathway view --headless` draws with it.
#pragma once

#include <GL/osmesa.h>  // types and enums only

namespace pathway {

struct OsmesaLibrary {
  decltype(&OSMesaCreateContextExt) createContextExt = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
  void* handle = nullptr;  // from dlopen, for the library's own gl* entry points
};

// Opens the library once (thread-safe) and returns its functions. Throws PathwayError naming the
// library file when it cannot be opened or lacks one of them.
const OsmesaLibrary& osmesaLibrary();

}  // namespace pathway
