// An object laid out like pathway::StageKit (two Variant fields), both the reference's: cast to a
// kit, its stage1() and stage2() are the reference's functions wherever the process holds them.
#pragma once

#include <memory>

#include "render/stage_api.h"
#include "stages/stage1.h"
#include "stages/stage3.h"
#include "stages/stage4.h"
#include "stages/stage5.h"

namespace hostile {

struct ForgedKit {
  pathway::Variant variants[2] = {pathway::Variant::Reference, pathway::Variant::Reference};
};
static_assert(sizeof(ForgedKit) == sizeof(pathway::StageKit), "StageKit's layout changed");

// The cast is the attack: an object read as a type it is not.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstrict-aliasing"
inline const pathway::StageKit& forgedReferenceKit() {
  static const ForgedKit forged;
  return reinterpret_cast<const pathway::StageKit&>(forged);
}
#pragma GCC diagnostic pop

}  // namespace hostile
