# A third held-out set of planted student bugs, for measuring how often the grader's likely
# cause is right on bugs its developers have never seen. Written by a separate reader who had
# NOT seen the diagnosis code (grade/difference_diagnosis.*, diagnosis_candidates.*,
# difference_patterns.*, robust_fit.*), its tests, docs/grading-course.md, or any grading report
# or mutant-causes output: only the assignment READMEs, the solutions, docs/grading.md (how the
# test works), the grading cases' scenes and settings (grading_cases.cpp, course_cases.cpp,
# scenes/scene_catalog.py), and the FORMAT of the existing mutant lists (to avoid repeating their
# edits). Every label below was chosen from the bug alone, before anything was built or graded;
# labels must not be changed after seeing the grader's output. Same format as
# heldout2_bugs.cmake (tests/mutants/CMakeLists.txt): each FROM text occurs in solutions/<file>
# and every occurrence is replaced, in order; no semicolon in a FROM or TO text (a TO text writes
# @SEMICOLON@). A label "fail:lit/scale" would accept either cause.

# ---------------------------------------------------------------- stage 1: filters and splat

# The student forgets the absolute value in the tent: 1 - x on [-1, 1] is a ramp from 2 to 0, a
# lopsided filter whose centre of weight sits a third of a pixel off the pixel centre. The
# image moves (tent cases only): shift.
pathway_mutant(h3_s1_tent_without_abs 1 stage1/stage1_filtering.cpp fail:shift
  "tent profile max(0, 1 - x) without the absolute value: a ramp, weight centred 1/3 pixel off"
  FROM "return std::max(0.0f, 1.0f - std::fabs(x))"
  TO "return std::max(0.0f, 1.0f - x)")

# Operator precedence: -x*x / 2*sigma*sigma is -(x^2 / 2) * sigma^2, so with sigma = 1/2 the
# bell is exp(-x^2 / 8), nearly flat over its support: a much wider, blurrier Gaussian. Edges.
pathway_mutant(h3_s1_gaussian_precedence 1 stage1/stage1_filtering.cpp fail:edges
  "Gaussian exponent written -x * x / 2 * sigma * sigma (sigma^2 multiplies instead of divides)"
  FROM "std::exp(-x * x / (2.0f * sigma * sigma))"
  TO "std::exp(-x * x / 2.0f * sigma * sigma)")

# "A weight cannot be negative": the student hands the film |f| instead of dropping negatives.
# Mitchell's negative lobes turn into positive ones: a wider, softer filter with no overshoot.
# Mitchell cases only. Filter profile: edges.
pathway_mutant(h3_s1_weight_magnitude 1 stage1/stage1_filtering.cpp fail:edges
  "splat adds abs(weight) (Mitchell's negative lobes become positive)"
  FROM "if (weight != 0.0f) film.addSample(x, y, weight, radiance)"
  TO "if (weight != 0.0f) film.addSample(x, y, std::fabs(weight), radiance)")

# Subtle: the student precomputes 7/3 as 2.33 in the outer piece. The lobe on 1 < |x| < 2 is
# a difference of large terms, so it becomes about 15 % shallower (and steps at |x| = 2). A
# small change of Mitchell's profile: edges.
pathway_mutant(h3_s1_mitchell_rounded_coefficient 1 stage1/stage1_filtering.cpp fail:edges
  "Mitchell outer cubic coefficient 7/3 rounded to 2.33 (lobes ~15 % shallower, subtle)"
  FROM "(-7.0f / 3.0f * a * a * a"
  TO "(-2.33f * a * a * a")

# The student "normalises the filter by its support area" on top of the film's division: every
# sample's radiance is divided by (2r)^2, so the whole image (background too) is darker by one
# factor (1/2.25 for the box of radius 0.75, 1/4 for the tent). Scale.
pathway_mutant(h3_s1_divided_by_support_area 1 stage1/stage1_filtering.cpp fail:scale
  "splat divides the radiance by the filter's support area (2r)^2 before adding it"
  FROM "film.addSample(x, y, weight, radiance)"
  TO "film.addSample(x, y, weight, radiance / (4.0f * r * r))")

# Solving |p - (j + 1/2)| <= r for j with the half on the wrong side: j in [p + 1/2 - r,
# p + 1/2 + r]. The window of pixels is one pixel too far right and down, so pixels whose
# centre lies up to one pixel left of / above the sample miss it: a lopsided reach. Shift.
pathway_mutant(h3_s1_window_half_wrong_sign 1 stage1/stage1_filtering.cpp fail:shift
  "splat window j in [p + 0.5 - r, p + 0.5 + r] (sign of the pixel-centre half flipped, x and y)"
  FROM "std::ceil(p.x - 0.5f - r)"
  TO "std::ceil(p.x + 0.5f - r)"
  FROM "std::floor(p.x - 0.5f + r)"
  TO "std::floor(p.x + 0.5f + r)"
  FROM "std::ceil(p.y - 0.5f - r)"
  TO "std::ceil(p.y + 0.5f - r)"
  FROM "std::floor(p.y - 0.5f + r)"
  TO "std::floor(p.y + 0.5f + r)")

# ---------------------------------------------------------------- stage 2: nested AO

# Y-up habit (glTF is y-up): the lift goes into local y. The pdf, asked with local.z = r sin phi,
# is 0 for half the directions (estimate 0); the rest form a lobe around the bitangent: about
# half the AO, in a wrong angular pattern. Factor and directions both wrong: occlusion or scale.
pathway_mutant(h3_s2_lift_into_y 2 stage2/stage2_nested_ao.cpp fail:occlusion/scale
  "cosine sample returned as (r cos phi, sqrt(1 - u1), r sin phi): the hemisphere around local y"
  FROM "return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)))"
  TO "return Vec3(r * std::cos(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)), r * std::sin(phi))")

# Copy-paste typo: cos(phi) in both disk coordinates. Every direction lies in one vertical
# plane of the local frame (and is not unit), so occluders off that plane are never seen and
# on the corner's floor the open quarter is never sampled. Direction distribution: occlusion.
pathway_mutant(h3_s2_cos_in_both_coordinates 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "Malley disk point (r cos phi, r cos phi): directions confined to one plane"
  FROM "return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)))"
  TO "return Vec3(r * std::cos(phi), r * std::cos(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)))")

# Stratification without the jitter: ray j takes u1 = j / M exactly (u2 still random). With
# M = 2 only the normal and the 45-degree ring are sampled (under the ceiling at D = 2 both are
# blocked: AO 0 instead of 1/4); at M = 128 the bias nearly vanishes. Occlusion.
pathway_mutant(h3_s2_strata_without_jitter 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "AO ray j uses u1 = j / M (strata without a random offset), u2 random"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "sum += ambientOcclusionSample(context, *hit, Vec2(static_cast<float>(j) / static_cast<float>(aoRays_), samples.next2D().y), aoDistance_)")

# The classic own basis: tangent = normalize(cross(n, up)) with up = +y, and cos taken from the
# world direction. On horizontal surfaces (floors, ceilings, block tops) the cross product is
# zero and the estimate is NaN; walls are right. One kind of hit broken (NaN): local.
pathway_mutant(h3_s2_basis_nan_on_horizontal 2 stage2/stage2_nested_ao.cpp fail:local
  "own basis from normalize(cross(n, +y)): NaN directions and estimates on horizontal surfaces"
  FROM "const Vec3 direction = Frame(hit.normal).toWorld(local)"
  TO "const Vec3 tangent = glm::normalize(glm::cross(hit.normal, Vec3(0.0f, 1.0f, 0.0f)))@SEMICOLON@
  const Vec3 bitangent = glm::cross(hit.normal, tangent)@SEMICOLON@
  const Vec3 direction = local.x * tangent + local.y * bitangent + local.z * hit.normal"
  FROM "return ambientOcclusionEstimate(blocked, local, pdf)"
  TO "return ambientOcclusionEstimate(blocked, Vec3(0.0f, 0.0f, glm::dot(direction, hit.normal)), pdf)")

# A wrong "running average": sum = (sum + estimate) / 2 and no division at the end. The weights
# 1/2^(M-j) add up to 1 - 2^-M: AO times 3/4 with two rays, 7/8 with three, ~1 with 128 (but
# there almost all weight is on the last rays: noisier). The mean is off by one factor: scale.
pathway_mutant(h3_s2_running_average_halves 2 stage2/stage2_nested_ao.cpp fail:scale
  "AO rays averaged as sum = (sum + estimate) / 2 (weights 1/2, 1/4, ... summing to 1 - 2^-M)"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "sum = 0.5f * (sum + ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_))"
  FROM "return Color(sum / aoRays_)"
  TO "return Color(sum)")

# The student writes the AO ray as origin + t (D w) with t in (0, 1]: the same segment of length
# D, the offset on the same side. The expectation and the rays per hit are unchanged: passes.
pathway_mutant(h3_s2_direction_times_distance 2 stage2/stage2_nested_ao.cpp pass
  "AO ray direction scaled by D with tMax = 1 (the same segment of length D)"
  FROM "const Ray aoRay = hit.spawnRay(direction, distance)"
  TO "const Ray aoRay = hit.spawnRay(direction * distance, 1.0f)")

# ---------------------------------------------------------------- stage 3: 4D AO

# A debugging constant left in: the pair is drawn but the AO direction comes from (1/2, 1/2),
# one fixed 45-degree direction per surface orientation. AO becomes the visibility along that
# one direction (the corner's floor: always blocked). Direction distribution: occlusion.
pathway_mutant(h3_s3_fixed_direction_sample 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "the drawn pair is ignored: every AO ray uses u = (0.5, 0.5)"
  FROM "const Vec2 directionSample = samples.next2D()"
  TO "samples.next2D()@SEMICOLON@
    const Vec2 directionSample(0.5f, 0.5f)")

# "Keep away from the poles": the pair clamped to [0.05, 0.95]. 5 % of the directions piled on
# each end of the elevation and azimuth ranges. Unchanged in the corner (infinite D) and under
# the ceiling (threshold inside the range); a small change where D is short: occlusion, subtle.
# (Since written, the case stage3-ceiling-near-pole puts the threshold below 0.05: caught there.)
pathway_mutant(h3_s3_pair_clamped 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "AO pair clamped to [0.05, 0.95] before the warp (piles up grazing/polar and phi ends)"
  FROM "const Vec2 directionSample = samples.next2D()"
  TO "const Vec2 directionSample = glm::clamp(samples.next2D(), 0.05f, 0.95f)")

# Carried over from stage 1's shading: AO times the eye-light |cos| between the normal and the
# view ray. Every hit is darkened by a factor (strongest at grazing views). An extra cosine on
# the AO part: scale.
pathway_mutant(h3_s3_times_view_cosine 3 stage3/stage3_ao_4d.cpp fail:scale
  "AO estimate multiplied by eyeLightCosine(hit, camera ray)"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return eyeLightCosine(*hit, cameraRay) * Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))")

# The student adds the 1/pi of AO(P) = (1/pi) integral ... on top of stage 2's estimate, which
# already includes it: every hit pixel is 1/pi as bright, the background unchanged. Scale.
pathway_mutant(h3_s3_extra_inv_pi 3 stage3/stage3_ao_4d.cpp fail:scale
  "AO estimate divided by pi once more"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return Color(kInvPi * stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))")

# Reading "the back of back_light must stay black" as a rule for every back face: hits on a
# back face return 0. Only the back of the open room's back_light is seen from behind. Local.
pathway_mutant(h3_s3_back_faces_black 3 stage3/stage3_ao_4d.cpp fail:local
  "camera hits on a back face return black instead of their AO"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return context.background()@SEMICOLON@
    if (!hit->frontFace) return Color(0.0f)")

# The student thinks the AO distance bounds every ray and gives the camera ray tMax = D too:
# surfaces farther than D from the eye show the background (the Cornell box at D = 0.3 and the
# room at D = 0.5 entirely; the far floor under the ceiling at D = 1.6). Background.
pathway_mutant(h3_s3_camera_ray_limited_to_distance 3 stage3/stage3_ao_4d.cpp fail:background
  "camera ray traced with tMax = ao-distance: farther surfaces come out as background"
  FROM "const auto hit = context.intersect(cameraRay, RayKind::Primary)"
  TO "Ray eyeRay = cameraRay@SEMICOLON@
    eyeRay.tMax = aoDistance_@SEMICOLON@
    const auto hit = context.intersect(eyeRay, RayKind::Primary)")

# ---------------------------------------------------------------- stage 4: naive recursion

# The wrong cosine: |cos| between the normal and the ray that arrived (the view ray), not the
# sampled branch. Each branch weighs rho cos(theta_o) / cos(theta_i): view-dependent and heavy
# tailed. A branch's weight wrong: lit.
pathway_mutant(h3_s4_cosine_of_arriving_ray 4 stage4/stage4_naive_recursion.cpp fail:lit
  "branch weight uses abs(cos) of the arriving ray instead of the branch direction's cos"
  FROM "reflected += brdf * incoming * local.z / pdf"
  TO "reflected += brdf * incoming * std::fabs(glm::dot(hit->normal, ray.direction)) / pdf")

# The BRDF written as the albedo (1/pi forgotten): every branch pi times too heavy, reflected
# light pi times (two bounces pi^2) too bright while emitters and background stay. A branch's
# weight (lit), and for one bounce one factor on all reflected light (scale).
pathway_mutant(h3_s4_brdf_without_inv_pi 4 stage4/stage4_naive_recursion.cpp fail:lit/scale
  "Lambertian BRDF taken as albedo instead of albedo / pi"
  FROM "const Color brdf = hit->albedo * kInvPi"
  TO "const Color brdf = hit->albedo")

# A rasterisation habit: an "ambient term" equal to the background added at every hit. Nothing
# changes in the Cornell box (black background); in the open room every surface gets extra sky
# light. What the background contributes is wrong: background.
pathway_mutant(h3_s4_background_as_ambient_term 4 stage4/stage4_naive_recursion.cpp fail:background
  "the background added at every hit as an ambient term"
  FROM "Color radiance = hit->emitted"
  TO "Color radiance = hit->emitted + context.background()")

# "A light does not reflect": recursion stops at any emitting hit. Only the Cornell light (albedo
# 0.78; the room's emitters are black) loses the light it reflects from the box, a few percent
# of its pixels. One kind of hit: local.
pathway_mutant(h3_s4_emitters_do_not_reflect 4 stage4/stage4_naive_recursion.cpp fail:local
  "recursion ends at emitting hits (an emitter's reflected light dropped)"
  FROM "if (bounce == depth_) return radiance"
  TO "if (bounce == depth_ || maxComponent(hit->emitted) > 0.0f) return radiance")

# "Average at the pixel": the branches are averaged only at the camera ray's hit and summed
# below it. With depth 1 nothing changes; with depth 2 (Cornell case, N = 2) the second bounce is
# N times too bright. Light after two bounces: indirect.
pathway_mutant(h3_s4_average_only_at_camera_hit 4 stage4/stage4_naive_recursion.cpp fail:indirect
  "the N branches averaged at bounce 0 only, summed at deeper hits"
  FROM "return radiance + reflected / static_cast<float>(branching_)"
  TO "return radiance + (bounce == 0 ? reflected / static_cast<float>(branching_) : reflected)")

# Radiance confused with exitance: the student divides the emission by pi ("power = pi x area x
# radiance"). Every emitter and all light it sends are 1/pi as bright; the background stays.
# One factor on the whole lit image: scale.
pathway_mutant(h3_s4_emission_over_pi 4 stage4/stage4_naive_recursion.cpp fail:scale
  "emitted radiance divided by pi"
  FROM "Color radiance = hit->emitted"
  TO "Color radiance = hit->emitted * kInvPi")

# ---------------------------------------------------------------- stage 5: path tracing

# = instead of *=: the throughput is replaced by each bounce's factor rho, not multiplied by it.
# NEE at the first two hits (throughput 1, then rho) is right; from the third hit on the path
# forgets the earlier albedos: light after two or more bounces too bright. Indirect.
pathway_mutant(h3_s5_throughput_assigned 5 stage5/stage5_path_tracing.cpp fail:indirect
  "throughput = brdf cos / pdf instead of throughput *= brdf cos / pdf"
  FROM "throughput *= brdf * local.z / pdf"
  TO "throughput = brdf * local.z / pdf")

# "NEE is for direct light": the shadow ray only at the camera ray's hit, while bounce rays
# still do not add emission (NEE on). Light after two or more bounces is lost; with NEE off
# nothing changes. Indirect.
pathway_mutant(h3_s5_nee_at_first_hit_only 5 stage5/stage5_path_tracing.cpp fail:indirect
  "next-event estimation only at bounce 0 (later hits get neither NEE nor bounce emission)"
  FROM "if (nextEventEstimation_) radiance += throughput * directLight(*hit, brdf, samples, context)"
  TO "if (nextEventEstimation_ && bounce == 0) radiance += throughput * directLight(*hit, brdf, samples, context)")

# Forgetting the square: the geometry term divides by the distance d, not d^2. Near the lights
# too dark, far from them too bright (the room's 2.5 m). The NEE geometry term: lit.
pathway_mutant(h3_s5_inverse_distance 5 stage5/stage5_path_tracing.cpp fail:lit
  "NEE geometry term divides by d instead of d^2"
  FROM "const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared"
  TO "const float geometry = cosSurface * std::fabs(cosLight) / std::sqrt(distanceSquared)")

# A self-intersection habit: the light point is pushed 1 cm off the emitter along its normal.
# The light acts as if 1 cm closer: ~2 % brighter at 1 m, much more near it, and wall points
# within 1 cm of the light touching it fall behind the moved point. Subtle: lit.
pathway_mutant(h3_s5_light_point_pushed_off 5 stage5/stage5_path_tracing.cpp fail:lit
  "sampled light point moved 1 cm along the emitter's normal (geometry from the moved point)"
  FROM "light.normal = e.normal"
  TO "light.normal = e.normal@SEMICOLON@
  light.position += 0.01f * e.normal")

# The student applies "NEE on: do not add what a bounce ray finds" to the background too. With
# NEE on the sky no longer lights anything through bounces (the open room darker; camera misses
# still show it); the Cornell box (black) and NEE off unchanged. Background.
pathway_mutant(h3_s5_background_only_with_emission 5 stage5/stage5_path_tracing.cpp fail:background
  "a missed bounce ray adds the background only when bounce emission is added (NEE off)"
  FROM "radiance += throughput * context.background()"
  TO "if (addEmission) radiance += throughput * context.background()")

# Wrong argument: the shadow ray's end is offset along the SURFACE's normal, not the light's.
# Under a parallel light (floor) that is the same; for walls and block sides the end stays in
# the light's plane and the emitter often blocks its own shadow ray. Direct light: lit.
pathway_mutant(h3_s5_shadow_end_offset_by_surface_normal 5 stage5/stage5_path_tracing.cpp fail:lit
  "spawnRayTo(light.position, hit.normal): the end moved off along the shading normal"
  FROM "hit.spawnRayTo(light.position, light.normal)"
  TO "hit.spawnRayTo(light.position, hit.normal)")

# NEE misunderstood as "one more random ray that counts the light it hits" (emission times rho;
# bounce emission still not added with NEE on). Each path counted once, so the mean is right,
# but the light is never sampled: the required technique is missing. Noise.
pathway_mutant(h3_s5_nee_as_extra_bounce_ray 5 stage5/stage5_path_tracing.cpp fail:noise
  "'NEE' is an extra cosine-weighted ray that adds the emission it hits (no light sampling)"
  FROM "const std::optional<DirectLight> light = directLightBeforeShadow(hit, brdf, samples)"
  TO "const Vec3 probe = stage2_.sampleCosineHemisphere(samples.next2D())@SEMICOLON@
    if (stage2_.cosineHemispherePdf(probe.z) <= 0.0f) return Color(0.0f)@SEMICOLON@
    const auto found =
        context.intersect(hit.spawnRay(Frame(hit.normal).toWorld(probe)), RayKind::Shadow)@SEMICOLON@
    return found ? brdf * kPi * found->emitted : Color(0.0f)"
  FROM "if (!light || context.occluded(light->shadowRay, RayKind::Shadow)) return Color(0.0f)"
  TO "(void)0"
  FROM "return light->value"
  TO "(void)0")

# The point's pair drawn before the emitter's number (the README leaves the order of draws to
# the student). Every number is still uniform and used once: the same expectation, NEE intact.
# Passes.
pathway_mutant(h3_s5_point_drawn_before_pick 5 stage5/stage5_path_tracing.cpp pass
  "NEE draws next2D() for the point before next1D() for the emitter"
  FROM "const float uPick = samples.next1D()"
  TO "const Vec2 uPointFirst = samples.next2D()@SEMICOLON@
    const float uPick = samples.next1D()"
  FROM "const Vec2 uPoint = samples.next2D()"
  TO "const Vec2 uPoint = uPointFirst")
