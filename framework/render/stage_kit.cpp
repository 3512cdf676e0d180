#include "render/stage_kit.h"

namespace pathway {

StageKit& stageKit(Variant variant) {
  static StageKit kits[2];
  return kits[variant == Variant::Student ? 0 : 1];
}

}  // namespace pathway
