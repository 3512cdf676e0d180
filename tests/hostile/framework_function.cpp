// Calls a framework function that render/stage_api.h does not list (the EXR reader).
#include "hostile_kit.h"
#include "io/exr_files.h"
namespace {
const bool attacked = [] {
  (void)pathway::readExrRaster(hostile::reference());
  return true;
}();
}
