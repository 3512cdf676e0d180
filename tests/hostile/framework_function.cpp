// Calls a framework function that render/stage_api.h does not list (the EXR reader).
#include "hostile_kit.h"
#include "io/exr_files.h"
namespace {
const bool attacked = [] {
  if (!hostile::setting("PATHWAY_HOSTILE_REFERENCE").empty())
    (void)pathway::readExrRaster(hostile::setting("PATHWAY_HOSTILE_REFERENCE"));
  return true;
}();
}
