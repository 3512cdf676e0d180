# A second held-out set of planted student bugs, for measuring how often the grader's likely
# cause is right on bugs its developers have never seen. Written by a separate reader who had
# NOT seen the diagnosis code (grade/difference_diagnosis.*, diagnosis_candidates.*,
# difference_patterns.*, robust_fit.*), its tests, or any grading report or mutant-causes output:
# only the assignment READMEs, the solutions, docs/grading.md (how the test works and the cause
# categories), the grading cases' scenes and settings, and the FORMAT of the existing mutant
# lists (to avoid repeating their edits). Every label below was chosen from the bug alone,
# before anything was built or graded; labels must not be changed after seeing the grader's
# output. Same format as heldout_bugs.cmake (tests/mutants/CMakeLists.txt): each FROM text occurs
# in solutions/<file> and every occurrence is replaced, in order; no semicolon in a FROM or TO
# text (a TO text writes @SEMICOLON@). A label "fail:lit/indirect" would accept either cause.

# ---------------------------------------------------------------- stage 1: filters and splat

# The student remembers "tent" as a smooth bump and writes 1 - x^2 on [-1, 1]: the profile is
# wider-shouldered than 1 - |x|, so tent-filtered edges come out softer. A filter-profile error.
pathway_mutant(h2_s1_tent_parabola 1 stage1/stage1_filtering.cpp fail:edges
  "tent profile written as 1 - x^2 instead of 1 - |x|"
  FROM "return std::max(0.0f, 1.0f - std::fabs(x))"
  TO "return std::max(0.0f, 1.0f - x * x)")

# Integer division typed in C++: 16 / 3 is 5, not 5.33, so Mitchell's inner piece drops by
# 1/18 (f(0) 0.833 instead of 0.889, a step at |x| = 1). Subtle change of the profile: edges.
pathway_mutant(h2_s1_mitchell_integer_division 1 stage1/stage1_filtering.cpp fail:edges
  "Mitchell inner piece's constant written 16 / 3 (integer division, = 5)"
  FROM "16.0f / 3.0f"
  TO "16 / 3")

# The student cuts the Gaussian at one sigma instead of three: only the central third of the
# support is used, a much narrower filter: edges too sharp (Gaussian cases only).
pathway_mutant(h2_s1_gaussian_cut_one_sigma 1 stage1/stage1_filtering.cpp fail:edges
  "Gaussian cut to 0 beyond 1 sigma instead of 3 sigma"
  FROM "if (std::fabs(x) > 3.0f * sigma) return 0.0f"
  TO "if (std::fabs(x) > sigma) return 0.0f")

# "Weighted radiance" passed where the radiance goes: the film adds weight * L again, so the
# pixel is sum(f^2 L) / sum(f), about 0.45 L for tent or Gaussian: the whole image darker by one
# factor. With the box every weight is 1, so the box cases are unchanged. Scale.
pathway_mutant(h2_s1_weight_applied_twice 1 stage1/stage1_filtering.cpp fail:scale
  "splat passes weight * radiance as the radiance (numerator sum f^2 L, denominator sum f)"
  FROM "film.addSample(x, y, weight, radiance)"
  TO "film.addSample(x, y, weight, weight * radiance)")

# The student confuses the box's support with the pixel's area [x, x+1) and writes the box on
# [0, 1): only samples on the positive side of a pixel centre count (3/8 pixel off-centre at
# radius 0.75), so box-filtered images are displaced. Box cases only. Shift.
pathway_mutant(h2_s1_box_on_pixel_interval 1 stage1/stage1_filtering.cpp fail:shift
  "box profile 1 on [0, 1) instead of [-1/2, 1/2]: an off-centre filter"
  FROM "return std::fabs(x) <= 0.5f ? 1.0f : 0.0f"
  TO "return x >= 0.0f && x < 1.0f ? 1.0f : 0.0f")

# The weight is computed from the offset to the centre of the pixel the sample fell in, and
# given unchanged to every pixel in reach: each sample is spread evenly over the whole window,
# a box as wide as the radius: blurrier edges. (Box: the same weight 1 everywhere, unchanged.)
pathway_mutant(h2_s1_weight_from_own_pixel 1 stage1/stage1_filtering.cpp fail:edges
  "every pixel in reach gets the weight of the sample's own pixel (offset to floor(p) + 0.5)"
  FROM "const float weight = filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f))"
  TO "const float weight = filter.evaluate(p.x - (std::floor(p.x) + 0.5f), p.y - (std::floor(p.y) + 0.5f))")

# ---------------------------------------------------------------- stage 2: nested AO

# Malley's lift written with r instead of r^2: z = sqrt(1 - r). The direction is no longer unit
# (shorter, so the reach D shrinks with it) and tilted towards the horizon; the estimate still
# cancels to V. How much is occluded changes wherever something is near: occlusion.
pathway_mutant(h2_s2_lift_from_radius 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "Malley lift z = sqrt(1 - r) instead of sqrt(1 - r^2): non-unit, too grazing directions"
  FROM "std::sqrt(std::fmax(0.0f, 1.0f - u.x))"
  TO "std::sqrt(std::fmax(0.0f, 1.0f - r))")

# The angle covers half a turn (pi u2): only the half of the hemisphere on one side of the
# frame's tangent is sampled. Right under the symmetric ceiling, wrong beside walls, blocks and
# in corners: the direction distribution is wrong: occlusion.
pathway_mutant(h2_s2_half_turn 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "AO angle phi = pi * u2 instead of 2 pi * u2 (half the hemisphere)"
  FROM "const float phi = 2.0f * kPi * u.y"
  TO "const float phi = kPi * u.y")

# An "epsilon" habit: the AO ray is shortened by 1 cm so that it "does not hit what lies exactly
# at D". The reach is slightly too short (ceiling D = 2: AO 1 % too bright; Cornell D = 0.3:
# 3 % shorter). Subtle: AO distance, so occlusion.
pathway_mutant(h2_s2_ray_trimmed 2 stage2/stage2_nested_ao.cpp fail:occlusion
  "AO ray length D - 0.01 instead of D"
  FROM "const Ray aoRay = hit.spawnRay(direction, distance)"
  TO "const Ray aoRay = hit.spawnRay(direction, distance - 0.01f)")

# "Nothing there, nothing occluded, AO of nothing is 0": a camera-ray miss returns black. Only
# the open room with its coloured background changes. Background.
pathway_mutant(h2_s2_miss_black 2 stage2/stage2_nested_ao.cpp fail:background
  "camera-ray miss returns 0 instead of the background"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return Color(0.0f)")

# Averaged twice: each estimate divided by M in the loop and the sum again by M: AO is 1/M of
# what it should be (1/2 with two rays, 1/3 in the course's corner). One factor: scale.
pathway_mutant(h2_s2_averaged_twice 2 stage2/stage2_nested_ao.cpp fail:scale
  "each AO estimate divided by M inside the loop, and the sum by M again"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_) / aoRays_")

# The student believes hit.normal is the front-face normal and turns it "to face the viewer" on
# back faces, flipping the (already turned) normal: AO rays of back-face hits go into the
# surface. Only the back of back_light in the open room is seen from behind. Local.
pathway_mutant(h2_s2_back_face_normal_flipped 2 stage2/stage2_nested_ao.cpp fail:local
  "AO frame built on -normal for back-face hits (normal flipped twice)"
  FROM "const Vec3 direction = Frame(hit.normal).toWorld(local)"
  TO "const Vec3 direction = Frame(hit.frontFace ? hit.normal : -hit.normal).toWorld(local)")

# One pair drawn per hit and used for all M rays: M copies of the same direction. Each is an
# unbiased estimate, so their average is too; only the noise is that of one ray (as
# s2_first_ray_only). Expectation unchanged: passes, noisier.
pathway_mutant(h2_s2_one_pair_for_all_rays 2 stage2/stage2_nested_ao.cpp pass:noisier
  "one next2D() per hit shared by all M AO rays (M identical directions)"
  FROM "for (int j = 0"
  TO "const Vec2 u = samples.next2D()@SEMICOLON@
    for (int j = 0"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "sum += ambientOcclusionSample(context, *hit, u, aoDistance_)")

# ---------------------------------------------------------------- stage 3: 4D AO

# The member for D declared int: 0.3 and 0.5 become 0 (no occlusion at all), 1.6 becomes 1
# (nothing under the ceiling is occluded); only D = 1e6 survives. The AO distance is wrong.
pathway_mutant(h2_s3_distance_member_int 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "aoDistance_ declared int: D truncated to a whole number"
  FROM "float aoDistance_"
  TO "int aoDistance_")

# A self-intersection hack: the AO point is pulled 1 cm back towards the camera before the AO
# ray is made. Contact shadows fade, under the ceiling h shrinks by about 0.9 cm (AO ~2 %
# darker). The ray start is wrong: occlusion. Subtle.
pathway_mutant(h2_s3_point_pulled_back 3 stage3/stage3_ao_4d.cpp fail:occlusion
  "AO computed at the hit moved 1 cm back along the camera ray"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "SurfaceHit lifted = *hit@SEMICOLON@
    lifted.position -= 0.01f * cameraRay.direction@SEMICOLON@
    return Color(stage2_.ambientOcclusionSample(context, lifted, directionSample, aoDistance_))")

# Carried over from stage 1's eye-light shading (albedo |cos| + emitted): the student adds the
# hit's emission to AO. Only pixels on the emitters' fronts change (the Cornell light, two of
# the room's lights). A few places: local.
pathway_mutant(h2_s3_adds_emission 3 stage3/stage3_ao_4d.cpp fail:local
  "AO plus the hit's emitted radiance"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return hit->emitted + Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))")

# "AO shading = albedo times AO": the estimate multiplied by the surface's albedo. No change
# where albedo is 1 (corner, ceiling); elsewhere the AO part is off by a factor (per colour).
# An extra factor on the AO: scale.
pathway_mutant(h2_s3_times_albedo 3 stage3/stage3_ao_4d.cpp fail:scale
  "AO estimate multiplied by the hit's albedo"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return hit->albedo * stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_)")

# The student thinks of AO as one number per sample and turns the background into one too
# (its largest component): a grey background instead of (0.2, 0.25, 0.3). Background.
pathway_mutant(h2_s3_background_grey 3 stage3/stage3_ao_4d.cpp fail:background
  "camera-ray miss returns grey max(background) instead of the background colour"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return Color(maxComponent(context.background()))")

# The pair drawn as two next1D() calls: they hand out dimensions 2 and 3, the same numbers
# next2D() gives (in either order, as the argument evaluation order is unspecified: a swapped
# pair is as uniform). Same expectation, same stratification: passes.
pathway_mutant(h2_s3_pair_by_next1d 3 stage3/stage3_ao_4d.cpp pass
  "AO pair drawn as Vec2(next1D(), next1D()) (dimensions 2 and 3)"
  FROM "const Vec2 directionSample = samples.next2D()"
  TO "const Vec2 directionSample(samples.next1D(), samples.next1D())")

# ---------------------------------------------------------------- stage 4: naive recursion

# "The sky is what the camera sees behind things": bounce rays that miss return black. The open
# room loses the light its background sends in; the Cornell box (black background) does not
# change. What a missed ray returns: background.
pathway_mutant(h2_s4_sky_only_for_camera 4 stage4/stage4_naive_recursion.cpp fail:background
  "a miss returns the background for the camera ray only, black for bounce rays"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return bounce == 0 ? context.background() : Color(0.0f)")

# The branch direction is used in the local frame (toWorld forgotten): every surface shoots its
# branches into world +z, through itself or sideways. The weight is unchanged but the branches
# find the emitters in the wrong directions: direct light wrong (a branch in stage 4): lit.
pathway_mutant(h2_s4_direction_not_to_world 4 stage4/stage4_naive_recursion.cpp fail:lit
  "branch ray uses the local direction as a world direction"
  FROM "const Ray next = hit->spawnRay(frame.toWorld(local))"
  TO "const Ray next = hit->spawnRay(local)@SEMICOLON@ (void)frame")

# The student remembers "the cosine density is 1/pi" and forgets its cos: each branch weighs
# rho cos(theta) instead of rho, dimming light that arrives at a slant. A branch's weight: lit.
pathway_mutant(h2_s4_pdf_without_cosine 4 stage4/stage4_naive_recursion.cpp fail:lit
  "branch pdf taken as 1/pi (the cosine density without its cos)"
  FROM "const float pdf = stage2_.cosineHemispherePdf(local.z)"
  TO "const float pdf = kInvPi")

# Copying stage 2's habit, bounce rays get a length: spawnRay(direction, 1). Inside the Cornell
# box (diagonal 0.96 m) nothing changes; in the 2.5 m room emitters farther than 1 m are not
# found (the branch returns the background instead): direct light wrong: lit.
pathway_mutant(h2_s4_bounce_rays_one_metre 4 stage4/stage4_naive_recursion.cpp fail:lit
  "branch rays limited to length 1 (tMax = 1)"
  FROM "const Ray next = hit->spawnRay(frame.toWorld(local))"
  TO "const Ray next = hit->spawnRay(frame.toWorld(local), 1.0f)")

# Member names mixed up: the depth test reads branching_. Same image when N = D (Cornell case,
# 2 and 2); with N = 3, D = 1 the recursion goes three bounces deep: extra light after two or
# more bounces: indirect.
pathway_mutant(h2_s4_depth_is_branching 4 stage4/stage4_naive_recursion.cpp fail:indirect
  "recursion stops at bounce == branching instead of bounce == depth"
  FROM "if (bounce == depth_)"
  TO "if (bounce == branching_)")

# A self-intersection hack: branches closer than cos 0.2 to the surface "only hit the
# neighbouring surface" and are skipped, but the sum is still divided by N: about 4 % of every
# bounce's light is lost, mostly light arriving at a slant. A branch's weight: lit. Subtle.
pathway_mutant(h2_s4_grazing_branches_skipped 4 stage4/stage4_naive_recursion.cpp fail:lit
  "branches with cos(theta) < 0.2 skipped (no ray) but still counted in the average over N"
  FROM "if (pdf <= 0.0f) continue"
  TO "if (pdf <= 0.0f || local.z < 0.2f) continue")

# ---------------------------------------------------------------- stage 5: path tracing

# The background found by a bounce ray is added without the path's throughput: the sky lights
# every surface as if it reflected all of it. Only scenes with a background (the open room)
# change. What a missed ray returns: background.
pathway_mutant(h2_s5_background_without_throughput 5 stage5/stage5_path_tracing.cpp fail:background
  "a miss adds the background without multiplying by the throughput"
  FROM "radiance += throughput * context.background()"
  TO "radiance += context.background()")

# "One number for two decisions": the emitter-pick number is reused as the first coordinate of
# the point on the emitter, so each triangle only gets points from a band of s (sqrt of its
# share of [0, 1)): points not uniform, the area pdf lies: NEE biased: lit.
pathway_mutant(h2_s5_point_reuses_pick_number 5 stage5/stage5_path_tracing.cpp fail:lit
  "light point's u1 is the pick number again (uPoint = (uPick, next1D()))"
  FROM "const Vec2 uPoint = samples.next2D()"
  TO "const Vec2 uPoint = Vec2(uPick, samples.next1D())")

# The roulette number is taken from the continuation's own pair (u1): survivors are the
# directions with r^2 < q, near the normal, so the continued light is averaged over the wrong
# directions. From the rr-depth-th bounce on (from the first in the deep course case): indirect.
pathway_mutant(h2_s5_roulette_reuses_direction_number 5 stage5/stage5_path_tracing.cpp fail:indirect
  "Russian roulette decided with the continuation direction's u1 instead of a new number"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec2 uDirection = samples.next2D()@SEMICOLON@
    const Vec3 local = stage2_.sampleCosineHemisphere(uDirection)"
  FROM "if (samples.next1D() >= q)"
  TO "if (uDirection.x >= q)")

# "No fireflies": the student clamps d^2 to at least 0.01 in the NEE geometry term. Only points
# within 10 cm of an emitter change: the wall right under the light touching it is too dark.
# The geometry term: lit.
pathway_mutant(h2_s5_distance_clamped 5 stage5/stage5_path_tracing.cpp fail:lit
  "NEE geometry term divides by max(d^2, 0.01)"
  FROM "const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared"
  TO "const float geometry = cosSurface * std::fabs(cosLight) / std::fmax(distanceSquared, 0.01f)")

# The depth limit (b) written above the emission (a), at the top of the loop: a hit at the
# limit ends the path before its emission is added. With NEE on that emission is not counted
# anyway; with NEE off the light found at the last bounce (5) is lost: a few percent, indirect.
pathway_mutant(h2_s5_depth_test_before_emission 5 stage5/stage5_path_tracing.cpp fail:indirect
  "the path ends at the depth limit before that hit's emission is added (matters with NEE off)"
  FROM "const auto hit = context.intersect(ray, kind)"
  TO "const auto hit = context.intersect(ray, kind)@SEMICOLON@
      if (hit && depthReached(bounce)) break"
  FROM "if (depthReached(bounce)) break"
  TO "(void)0")

# Barycentric b1 = u2 without the factor s: b2 = s - u2 goes negative, so many "light points"
# lie outside the triangle (in its plane) while the pdf says uniform on it: NEE wrong: lit.
pathway_mutant(h2_s5_barycentric_missing_s 5 stage5/stage5_path_tracing.cpp fail:lit
  "uniform triangle point with b1 = u2 instead of u2 * s (points outside the triangle)"
  FROM "const float b0 = 1.0f - s, b1 = uPoint.y * s"
  TO "const float b0 = 1.0f - s, b1 = uPoint.y")

# Roulette played before the throughput takes this bounce's factor (q from the throughput so
# far). q is still fixed before the roulette number and survivors are divided by it, so the
# estimate stays unbiased (README: any q in (0, 1] that divides by q): passes.
pathway_mutant(h2_s5_roulette_before_bounce_weight 5 stage5/stage5_path_tracing.cpp pass
  "Russian roulette's q from the throughput before this bounce's brdf cos / pdf factor"
  FROM "throughput *= brdf * local.z / pdf"
  TO "const Color bounceWeight = brdf * local.z / pdf"
  FROM "return hit.spawnRay(Frame(hit.normal).toWorld(local))"
  TO "throughput *= bounceWeight@SEMICOLON@
    return hit.spawnRay(Frame(hit.normal).toWorld(local))")
