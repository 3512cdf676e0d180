// The stage kit: what earlier stages hand on to the later ones, as in the lecture. Stage 1's
// filters and splat serve every stage (the renderer splats with them); stage 2's cosine-weighted
// hemisphere sampling and AO estimate serve stages 3-5. Stage 5's light sampling serves no later
// stage, only the warp test (grade/warp_fit.h), which tests it as it tests stage 2's directions.
//
// Each variant (the student's, and the reference when solutions/ is built in) provides its own
// stage 1 and stage 2 functions when its stage files register. A kit picks, for each earlier
// stage, which variant's functions to use: usually the integrator's own, but the grader can put a
// student's stage 3 on the reference's stages 1-2, so that one bug costs points only once.
#pragma once

#include <string>

#include "core/math.h"
#include "core/variant.h"
#include "film/film.h"
#include "film/pixel_filter.h"
#include "render/emitter_picker.h"
#include "render/integrator.h"

namespace pathway {

// What stage 1 hands on.
struct Stage1Functions {
  FilterProfiles profiles;
  // Adds f_j·L and f_j to every pixel j whose filter support holds the sample at `position`.
  void (*splat)(FilmBlock& film, Vec2 position, const Color& radiance,
                const PixelFilter& filter) = nullptr;
};

// What stage 2 hands on.
struct Stage2Functions {
  // A direction in the local frame (z along the normal) with density cos θ / π ...
  Vec3 (*sampleCosineHemisphere)(Vec2 u) = nullptr;
  // ... that density, per unit solid angle, for a direction with the given cos θ.
  float (*cosineHemispherePdf)(float cosTheta) = nullptr;
  // One AO direction from `u`, traced up to `distance`: V·cos θ / (π·pdf).
  float (*ambientOcclusionSample)(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                                  float distance) = nullptr;
};

// What stage 5 hands on (to the warp test).
struct Stage5Functions {
  // A point on the emitters for next-event estimation: `lights.pick(uPick)` chooses a triangle,
  // `uPoint` the point on it; with its density per unit area over all emitters.
  LightSample (*sampleLight)(const EmitterPicker& lights, float uPick, Vec2 uPoint) = nullptr;
};

// Where an integrator's earlier stages come from.
enum class EarlierStages {
  Own,        // the integrator's own variant: your stage 3 uses your stages 1-2
  Reference,  // the reference's: your stage 3 on the reference's stages 1-2 (grading one stage)
};
std::string earlierStagesName(EarlierStages source);  // "own", "reference"
// Throws PathwayError naming the choices.
EarlierStages parseEarlierStages(const std::string& name);

class StageKit {
 public:
  // The kit an integrator of `stage` (0: not a course stage) in `variant` works with: stages
  // before `stage` from `earlier`, the others (its own stage included) from `variant`.
  StageKit(int stage, Variant variant, EarlierStages earlier);

  // The functions of stage 1 / stage 2 in this kit. Throws PathwayError naming the stage and
  // the variant when that stage is not built into this program.
  const Stage1Functions& stage1() const;
  const Stage2Functions& stage2() const;

  Variant stage1Variant() const { return variants_[0]; }
  Variant stage2Variant() const { return variants_[1]; }

 private:
  Variant variants_[2];
};

// Stage 5's functions in `variant`. Throws PathwayError naming the stage and the variant when
// that stage is not built into this program.
const Stage5Functions& stage5Functions(Variant variant);

// Called when a variant's stage 1, 2 or 5 file registers (see render/stage_api.h).
void provideStage1(Variant variant, const Stage1Functions& functions);
void provideStage2(Variant variant, const Stage2Functions& functions);
void provideStage5(Variant variant, const Stage5Functions& functions);

}  // namespace pathway
