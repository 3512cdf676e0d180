# A fourth held-out set of planted student bugs, for measuring how often the grader's likely
# cause is right on bugs its developers have never seen. Written by a separate reader who had
# NOT seen the diagnosis code (grade/difference_diagnosis.*, diagnosis_candidates.*,
# difference_patterns.*, robust_fit.*), its tests, docs/grading-course.md, git history, or any
# grading report or mutant-causes output: only the assignment READMEs, the solutions, the stage
# API and the framework headers it names (only to make each edit compile), docs/grading.md (how
# the test works and what each cause means), the grading cases' scenes and settings
# (grading_cases.cpp, course_cases.cpp, scenes/scene_catalog.py), and the FORMAT and bug lists of
# the earlier sets (to copy the format and to avoid repeating their edits and ideas). Every label
# below was chosen from the bug alone, before anything was built or graded; labels must not be
# changed after seeing the grader's output. Same format as heldout3_bugs.cmake
# (tests/mutants/CMakeLists.txt): each FROM text occurs in solutions/<file> and every occurrence
# is replaced, in order; no semicolon in a FROM or TO text (a TO text writes @SEMICOLON@). A
# label "fail:lit/local" would accept either cause.

# ---------------------------------------------------------------- stage 1: filters and splat

# The student thinks evaluate() takes offsets in units of the radius and divides by r: the box
# (r 0.75) shrinks to r^2 = 0.56, Mitchell and the Gaussians widen (the tent at r = 1 is unchanged).
pathway_mutant(h4_s1_offsets_in_radius_units 1 stage1/stage1_filtering.cpp fail:edges
  "splat passes dx / r and dy / r to filter.evaluate (offsets 'normalised' by the radius)"
  FROM "filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f))"
  TO "filter.evaluate((p.x - (x + 0.5f)) / r, (p.y - (y + 0.5f)) / r)")

# The half-pixel to the pixel centre confused with the filter's radius: the filter sits r - 1/2
# off the pixel centre in x and y (and is cut on one side by the unchanged window). Image moves.
pathway_mutant(h4_s1_pixel_centre_at_radius 1 stage1/stage1_filtering.cpp fail:shift
  "filter offsets measured from (x + r, y + r) instead of the pixel centre (x + 0.5, y + 0.5)"
  FROM "filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f))"
  TO "filter.evaluate(p.x - (x + r), p.y - (y + r))")

# The / 6 forgotten on Mitchell's outer piece only: the lobe on 1 < |x| < 2 is six times too
# strong (a positive ring, then a deep negative one). Mitchell's profile: edges.
pathway_mutant(h4_s1_mitchell_outer_not_divided 1 stage1/stage1_filtering.cpp fail:edges
  "Mitchell outer piece not divided by 6 (its lobes six times too strong)"
  FROM "+ 32.0f / 3.0f) / 6.0f"
  TO "+ 32.0f / 3.0f)")

# One factor a lost in the inner cubic: 7 a^2 instead of 7 a^3. Same values at 0 and 1, but the
# central lobe is fatter in between (0.68 instead of 0.54 at a = 1/2): blurrier. Edges.
pathway_mutant(h4_s1_mitchell_inner_square 1 stage1/stage1_filtering.cpp fail:edges
  "Mitchell inner piece with 7 a^2 instead of 7 a^3 (a factor a lost)"
  FROM "7.0f * a * a * a - 12.0f * a * a"
  TO "7.0f * a * a - 12.0f * a * a")

# The skeleton's placeholder (each sample into its own pixel with weight 1) is left in beside the
# new splat: every filter becomes itself plus a one-pixel box, a sharper mixture. Edges.
pathway_mutant(h4_s1_skeleton_splat_left_in 1 stage1/stage1_filtering.cpp fail:edges
  "the skeleton's own-pixel addSample(weight 1) kept in addition to the filtered splat"
  FROM "const float r = filter.radius()"
  TO "film.addSample(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), 1.0f, radiance)@SEMICOLON@
  const float r = filter.radius()")

# "A radius counts pixels": r stored as an int. The box (0.75 -> 0) reaches no pixel at all, so
# box images come out black (scale); the Gaussians and the wide tent lose their tails (edges).
pathway_mutant(h4_s1_integer_radius 1 stage1/stage1_filtering.cpp fail:edges/scale
  "splat truncates filter.radius() to an int (0.75 -> 0, 1.5 -> 1, 2.5 -> 2)"
  FROM "const float r = filter.radius()"
  TO "const int r = static_cast<int>(filter.radius())")

# ---------------------------------------------------------------- stage 2: nested AO

# Wrong variable: the disk radius from u2, the number the angle uses. The disk point runs on a
# spiral (r tied to phi) and the lifted vector is not unit: wrong directions and reach. Occlusion.
pathway_mutant(h4_s2_radius_from_angle_number 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "Malley disk radius sqrt(u2) instead of sqrt(u1) (z still from u1, phi from u2)"
  FROM "const float r = std::sqrt(u.x)"
  TO "const float r = std::sqrt(u.y)")

# D read as a height above the surface: each AO ray gets length D / cos(theta). Under the
# ceiling (D = 2) every ray now reaches it (AO 0 instead of 1/4); grazing rays reach far. Occlusion.
pathway_mutant(h4_s2_reach_as_height 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "AO ray length D / cos(theta) (D taken as the height the ray must rise), not D"
  FROM "const Ray aoRay = hit.spawnRay(direction, distance)"
  TO "const Ray aoRay = hit.spawnRay(direction, distance / local.z)")

# A home-made stratification: one pair per hit, ray j turns it by j/M in azimuth and keeps its
# elevation. Unbiased, but under the symmetric ceiling all 128 rays agree: one ray's noise. Noise.
pathway_mutant(h4_s2_azimuth_strata_shared_elevation 2 stage2/stage2_nested_ao.cpp fail:noise
  "one next2D() per hit: ray j uses (u1, frac(u2 + j/M)), the same elevation number for all M rays"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return context.background()@SEMICOLON@
    const Vec2 u = samples.next2D()"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "sum += ambientOcclusionSample(context, *hit, Vec2(u.x, std::fmod(u.y + static_cast<float>(j) / static_cast<float>(aoRays_), 1.0f)), aoDistance_)")

# Stratifying u1 as j + u1, the / M forgotten: for j >= 1 the number is >= 1, the lift gives
# z = 0, pdf 0, estimate 0. Only ray 0 counts, still divided by M: AO / M. Scale.
pathway_mutant(h4_s2_strata_offset_not_divided 2 stage2/stage2_nested_ao.cpp fail:scale
  "AO ray j uses u1 = j + u1 (stratum offset without / M): rays j >= 1 get pdf 0"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "{
        const Vec2 u = samples.next2D()@SEMICOLON@
        sum += ambientOcclusionSample(context, *hit, Vec2(static_cast<float>(j) + u.x, u.y), aoDistance_)@SEMICOLON@
      }")

# "Once a ray is blocked the point is occluded": break at the first blocked ray, still / M, so
# AO a becomes (a + a^2) / 2: occluded parts darker (occlusion), a factor where AO is even (scale).
pathway_mutant(h4_s2_early_exit_when_blocked 2 stage2/stage2_nested_ao.cpp fail:occlusion/scale
  "AO loop breaks at the first blocked ray but still divides by M"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "{
        const float estimate = ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)@SEMICOLON@
        sum += estimate@SEMICOLON@
        if (estimate == 0.0f) break@SEMICOLON@
      }")

# A constant from testing at the default ao-rays = 4: the sum divided by 4, not M. Every hit pixel
# by one factor per case (1/2 at M = 2, 3/4 at M = 3, 32 at M = 128), misses unchanged. Scale.
pathway_mutant(h4_s2_divided_by_default_rays 2 stage2/stage2_nested_ao.cpp fail:scale
  "the M AO estimates summed and divided by 4 (the default ao-rays) instead of M"
  FROM "return Color(sum / aoRays_)"
  TO "return Color(sum / 4.0f)")

# "Lights cast no ambient shadow": an AO ray whose first hit is an emitter's front counts as open,
# though the wall or ceiling right behind it is within D. Only near the emitters: occlusion/local.
pathway_mutant(h4_s2_emitters_do_not_occlude 2 stage2/stage2_nested_ao.cpp fail:occlusion/local
  "AO rays that first hit an emitting surface count as unblocked"
  FROM "const bool blocked = context.occluded(aoRay, RayKind::Secondary)"
  TO "const auto blocker = context.intersect(aoRay, RayKind::Secondary)@SEMICOLON@
  const bool blocked = blocker && maxComponent(blocker->emitted) <= 0.0f")

# ---------------------------------------------------------------- stage 3: 4D AO

# "No pitch black": the estimate clamped below at 0.1. With cosine sampling it is 0 or 1, so the
# image is 0.1 + 0.9 AO: 0.1 times (unoccluded minus AO) added on every hit. Occlusion.
pathway_mutant(h4_s3_ambient_floor 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "AO estimate clamped to at least 0.1 (an ambient floor)"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return Color(std::fmax(0.1f, stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_)))")

# Wrong frame: the AO hemisphere is built around the direction back to the eye, not the normal.
# At slanted views half of it dips under the surface and is blocked: a wrong AO pattern. Occlusion.
pathway_mutant(h4_s3_hemisphere_around_view 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "AO computed with the hit's normal replaced by the direction towards the camera"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "SurfaceHit facing = *hit@SEMICOLON@
    facing.normal = glm::normalize(-cameraRay.direction)@SEMICOLON@
    return Color(stage2_.ambientOcclusionSample(context, facing, directionSample, aoDistance_))")

# The cosine counted twice (the estimate already holds V cos / (pi p)): AO weighted by cos^2, 2/3
# when open, exactly 2/3 in the corner, less where occluded. Mostly a factor (scale), some pattern.
pathway_mutant(h4_s3_cosine_applied_twice 3 stage3/stage3_ao_4d.cpp fail:scale/occlusion
  "AO estimate multiplied by the sampled direction's cos(theta) once more"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_) * stage2_.sampleCosineHemisphere(directionSample).z)")

# A number used for two decisions: the AO reach randomised as D * u1 with the u1 that also sets
# the elevation (grazing rays long, steep ones short). Under the course ceiling AO becomes 1.
pathway_mutant(h4_s3_reach_from_direction_number 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "AO ray length D * u1, u1 being the direction's own first number"
  FROM "*hit, directionSample, aoDistance_)"
  TO "*hit, directionSample, aoDistance_ * directionSample.x)")

# ---------------------------------------------------------------- stage 4: naive recursion

# A firefly habit: what a branch brings back is scaled down to a largest component of 1. Only
# emitters are that bright, so each emitter's light drops by its own factor. Direct light: lit.
pathway_mutant(h4_s4_incoming_clamped 4 stage4/stage4_naive_recursion.cpp fail:lit
  "each branch's incoming radiance scaled down to a largest component of at most 1"
  FROM "const Color incoming = trace(next, RayKind::Secondary, bounce + 1, samples, context)"
  TO "const Color traced = trace(next, RayKind::Secondary, bounce + 1, samples, context)@SEMICOLON@
      const Color incoming = traced / std::fmax(1.0f, maxComponent(traced))")

# Radiance confused with intensity: emission times |cos| between the emitter's normal and the ray
# that sees it. Emitters look dimmer edge-on and light the room with an extra cos: lit.
pathway_mutant(h4_s4_emission_times_view_cosine 4 stage4/stage4_naive_recursion.cpp fail:lit
  "emitted radiance multiplied by abs(cos) between the hit normal and the arriving ray"
  FROM "Color radiance = hit->emitted"
  TO "Color radiance = hit->emitted * std::fabs(glm::dot(hit->normal, glm::normalize(ray.direction)))")

# Parentheses: (emission + sum) / N, so the emission of every hit above the deepest level is
# divided by N. Depth 1: only emitters the camera sees (local); Cornell, depth 2: direct light / 2.
pathway_mutant(h4_s4_emission_divided_by_branches 4 stage4/stage4_naive_recursion.cpp fail:lit/local
  "returns (emitted + sum of branches) / N: the hit's own emission divided by N too"
  FROM "return radiance + reflected / static_cast<float>(branching_)"
  TO "return (radiance + reflected) / static_cast<float>(branching_)")

# An outdoor habit: the sky only above the horizon, black below. In the open room camera rays past
# the floor's edges and downward bounce rays out of the openings return black. Background.
pathway_mutant(h4_s4_sky_only_above_horizon 4 stage4/stage4_naive_recursion.cpp fail:background
  "a miss returns the background only for rays going up (direction.y > 0), black otherwise"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return ray.direction.y > 0.0f ? context.background() : Color(0.0f)")

# = for +=: each branch overwrites the last, so only the last of N branches counts, still divided
# by N. All reflected light 1/N (1/N^2 after two bounces): a branch's weight, lit.
pathway_mutant(h4_s4_branch_overwritten 4 stage4/stage4_naive_recursion.cpp fail:lit
  "reflected = (not +=) the branch term: only the last branch kept, divided by N"
  FROM "reflected += brdf * incoming * local.z / pdf"
  TO "reflected = brdf * incoming * local.z / pdf")

# Wrong variable: the recursion traces `ray` (the ray that arrived) instead of `next`; it meets the
# same surface again, so a branch brings back that surface's own emission. No reflected light: lit.
pathway_mutant(h4_s4_recursion_on_same_ray 4 stage4/stage4_naive_recursion.cpp fail:lit
  "each branch recurses on the arriving ray instead of the new branch ray"
  FROM "const Color incoming = trace(next, RayKind::Secondary, bounce + 1, samples, context)"
  TO "(void)next@SEMICOLON@
      const Color incoming = trace(ray, RayKind::Secondary, bounce + 1, samples, context)")

# ---------------------------------------------------------------- stage 5: path tracing

# Inverted comparison: the path ends when the number is below q, survives with 1 - q, still / q.
# Only light after the roulette bounces changes (rr-depth 1: from the first bounce ray): indirect.
pathway_mutant(h4_s5_roulette_test_inverted 5 stage5/stage5_path_tracing.cpp fail:indirect
  "Russian roulette ends the path when next1D() < q (survives with 1 - q), divides by q"
  FROM "if (samples.next1D() >= q) return std::nullopt"
  TO "if (samples.next1D() < q) return std::nullopt")

# Order of steps: the continuation (and its throughput update) is made before NEE, so every hit's
# direct light is weighted by that hit's own albedo (and 1/q). Direct light too dark: lit.
pathway_mutant(h4_s5_nee_after_bounce_weight 5 stage5/stage5_path_tracing.cpp fail:lit
  "NEE added after continuation() updated the throughput with this hit's brdf cos / pdf"
  FROM "if (nextEventEstimation_) radiance += throughput * directLight(*hit, brdf, samples, context)"
  TO "(void)0"
  FROM "const std::optional<Ray> next = continuation(*hit, brdf, bounce, throughput, samples)"
  TO "const std::optional<Ray> next = continuation(*hit, brdf, bounce, throughput, samples)@SEMICOLON@
      if (nextEventEstimation_) radiance += throughput * directLight(*hit, brdf, samples, context)")

# * for /: the area density written probability * area. Each emitter's NEE term is off by
# 1 / area^2 of its triangles, a different (huge) factor per emitter. Lit.
pathway_mutant(h4_s5_area_pdf_times_area 5 stage5/stage5_path_tracing.cpp fail:lit
  "light pdfArea = probability * area instead of probability / area"
  FROM "light.pdfArea = pick.probability / e.area"
  TO "light.pdfArea = pick.probability * e.area")

# The NEE rule written once at the start: addEmission = !nee from the camera ray on, so with NEE
# on the emitters the camera sees are black. A few places (NEE off unchanged): local.
pathway_mutant(h4_s5_camera_misses_emitters_with_nee 5 stage5/stage5_path_tracing.cpp fail:local
  "addEmission starts as !nee: with NEE on the camera ray's emission is not added either"
  FROM "Ray ray = cameraRay"
  TO "const bool isNee = nextEventEstimation_@SEMICOLON@
    Ray ray = cameraRay"
  FROM "w.active.resize(n)"
  TO "w.active.resize(n)@SEMICOLON@
    const bool isNee = path_.nextEventEstimation()"
  FROM "bool addEmission = true"
  TO "bool addEmission = !isNee")

# The albedo applied twice (continuation() already took rho, Li multiplies again): NEE at the first
# hit right, later hits too dark (indirect); with NEE off light found by a bounce loses a rho (lit).
pathway_mutant(h4_s5_albedo_applied_twice 5 stage5/stage5_path_tracing.cpp fail:indirect/lit
  "Li also multiplies the throughput by the hit's albedo before following the next ray"
  FROM "ray = *next"
  TO "throughput *= hit->albedo@SEMICOLON@
      ray = *next")

# A misplaced !: NEE counts the light only when the shadow ray IS blocked. Lit regions lose their
# direct light, shadows get it. Direct light: lit.
pathway_mutant(h4_s5_shadow_test_inverted 5 stage5/stage5_path_tracing.cpp fail:lit
  "NEE returns 0 when the shadow ray is NOT blocked (test inverted)"
  FROM "if (!light || context.occluded(light->shadowRay, RayKind::Shadow)) return Color(0.0f)"
  TO "if (!light || !context.occluded(light->shadowRay, RayKind::Shadow)) return Color(0.0f)")

# Wrong vector normalised: the direction to the light is the light point's position from the
# world origin, not from the hit. Both cosines wrong (some walls get none); d^2 right. Lit.
pathway_mutant(h4_s5_direction_from_light_position 5 stage5/stage5_path_tracing.cpp fail:lit
  "NEE direction normalize(light.position) instead of (light.position - hit.position) / d"
  FROM "const Vec3 direction = toLight / std::sqrt(distanceSquared)"
  TO "const Vec3 direction = glm::normalize(light.position)")
