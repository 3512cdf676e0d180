#include "stages/stage_catalog.h"

#include "core/error.h"
#include "stages/stage1.h"
#include "stages/stage2.h"
#include "stages/stage3.h"
#include "stages/stage4.h"
#include "stages/stage5.h"

namespace pathway {

const StageInfo& stageInfo(int stage) {
  static const std::vector<StageInfo> stages = {stage1().info(), stage2().info(), stage3().info(),
                                                stage4().info(), stage5().info()};
  if (stage < 1 || stage > kStageCount)
    throw PathwayError("there is no stage " + std::to_string(stage) + " (stages are 1 to " +
                       std::to_string(kStageCount) + ")");
  return stages[stage - 1];
}

}  // namespace pathway
