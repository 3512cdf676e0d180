// Included by every stage file (assignments/ and solutions/): what a stage may use, and which
// variant (student or reference) is being compiled.
#pragma once

#include "core/math.h"
#include "core/todo.h"
#include "core/variant.h"
#include "film/pixel_filter.h"
#include "render/eye_light_integrator.h"
#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "render/stage_kit.h"
#include "scene/ray_tracer.h"

#if defined(PATHWAY_VARIANT_REFERENCE)
#define PATHWAY_THIS_VARIANT ::pathway::Variant::Reference
#elif defined(PATHWAY_VARIANT_STUDENT)
#define PATHWAY_THIS_VARIANT ::pathway::Variant::Student
#else
#error "stage files are compiled as part of pathway_stages_student or pathway_stages_reference"
#endif
