# Valid variants: correct stages written another way (another warp, basis, roulette rule,
# splat range, filter form, NEE form), each estimating the reference's expected image.
# The grader must pass them (expect: pass). Each comment says why it is correct.
# tests/mutants/CMakeLists.txt builds them on demand (target pathway_mutants_variants), never in
# the suite; scripts/mutant-causes variants grades them.

# Helpers more than one variant adds to its stage file, written once (CMake expands them in the
# TO texts below).
set(PATHWAY_VARIANT_CONCENTRIC_COSINE "// Cosine-weighted direction by Shirley & Chiu's concentric map: the unit square, stretched to
// side 2 around 0, onto the unit disk (area-preserving up to the constant π/4: uniform in,
// uniform out), then lifted to z.
Vec3 sampleConcentricCosine(Vec2 u) {
  const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f@SEMICOLON@
  float r = 0.0f, phi = 0.0f@SEMICOLON@
  if (a != 0.0f || b != 0.0f) {
    if (std::fabs(a) > std::fabs(b)) {
      r = a@SEMICOLON@
      phi = 0.25f * kPi * (b / a)@SEMICOLON@
    } else {
      r = b@SEMICOLON@
      phi = 0.5f * kPi - 0.25f * kPi * (a / b)@SEMICOLON@
    }
  }
  const float x = r * std::cos(phi), y = r * std::sin(phi)@SEMICOLON@
  return Vec3(x, y, std::sqrt(std::fmax(0.0f, 1.0f - r * r)))@SEMICOLON@
}")
set(PATHWAY_VARIANT_GRAM_SCHMIDT "// An orthonormal basis around n by Gram-Schmidt: take an axis not too close to n, remove its
// component along n, normalise, and complete with a cross product.
Vec3 gramSchmidtToWorld(const Vec3& n, const Vec3& local) {
  const Vec3 helper = std::fabs(n.x) > 0.9f ? Vec3(0.0f, 1.0f, 0.0f) : Vec3(1.0f, 0.0f, 0.0f)@SEMICOLON@
  const Vec3 t = glm::normalize(helper - glm::dot(helper, n) * n)@SEMICOLON@
  const Vec3 b = glm::cross(n, t)@SEMICOLON@
  return local.x * t + local.y * b + local.z * n@SEMICOLON@
}")
set(PATHWAY_VARIANT_FRISVAD "// Frisvad's (2012) branch-free basis around a unit n, with its special case at n = -z.
Vec3 frisvadToWorld(const Vec3& n, const Vec3& local) {
  Vec3 b1, b2@SEMICOLON@
  if (n.z < -0.9999999f) {
    b1 = Vec3(0.0f, -1.0f, 0.0f)@SEMICOLON@
    b2 = Vec3(-1.0f, 0.0f, 0.0f)@SEMICOLON@
  } else {
    const float a = 1.0f / (1.0f + n.z)@SEMICOLON@
    const float b = -n.x * n.y * a@SEMICOLON@
    b1 = Vec3(1.0f - n.x * n.x * a, b, -n.x)@SEMICOLON@
    b2 = Vec3(b, 1.0f - n.y * n.y * a, -n.y)@SEMICOLON@
  }
  return local.x * b1 + local.y * b2 + local.z * n@SEMICOLON@
}")
set(PATHWAY_VARIANT_UNIFORM_HEMISPHERE "// Uniform on the hemisphere (Archimedes: cos θ is uniform between 0 and 1), density 1 / (2π).
Vec3 sampleUniformHemisphere(Vec2 u) {
  const float z = 1.0f - u.x@SEMICOLON@  // never 0: never exactly in the surface plane
  const float r = std::sqrt(std::fmax(0.0f, 1.0f - z * z))@SEMICOLON@
  const float phi = 2.0f * kPi * u.y@SEMICOLON@
  return Vec3(r * std::cos(phi), r * std::sin(phi), z)@SEMICOLON@
}")
set(PATHWAY_VARIANT_UNIFORM_PDF "float uniformHemispherePdf(float cosTheta) {
  return cosTheta > 0.0f ? 0.5f * kInvPi : 0.0f@SEMICOLON@
}")

# The pixels whose centre is within r of p (j in [p-0.5-r, p-0.5+r]) all lie in
# floor(p) - ceil(r) .. floor(p) + ceil(r); the extra pixels get f = 0 from filter.evaluate (it is
# 0 beyond radius()), and the weight != 0 test skips them: the same sums as the reference.
pathway_mutant(v_s1_splat_cell_window 1 stage1/stage1_filtering.cpp pass "splat loops over floor(p) +- ceil(r), a superset of the pixels in reach"
  FROM "static_cast<int>(std::ceil(p.x - 0.5f - r))"
  TO "static_cast<int>(std::floor(p.x)) - static_cast<int>(std::ceil(r))"
  FROM "static_cast<int>(std::floor(p.x - 0.5f + r))"
  TO "static_cast<int>(std::floor(p.x)) + static_cast<int>(std::ceil(r))"
  FROM "static_cast<int>(std::ceil(p.y - 0.5f - r))"
  TO "static_cast<int>(std::floor(p.y)) - static_cast<int>(std::ceil(r))"
  FROM "static_cast<int>(std::floor(p.y - 0.5f + r))"
  TO "static_cast<int>(std::floor(p.y)) + static_cast<int>(std::ceil(r))")

# A superset of the pixels in reach, each tested explicitly with |dx|, |dy| <= r (the same
# test the filter makes), and every pixel in reach is added even with weight 0 (adds nothing). Same
# sums as the reference.
pathway_mutant(v_s1_splat_wide_box 1 stage1/stage1_filtering.cpp pass "splat loops over a generous box (floor/ceil of p -+ r, one more each side), skips by |d| > r"
  FROM "static_cast<int>(std::ceil(p.x - 0.5f - r))"
  TO "static_cast<int>(std::floor(p.x - r)) - 1"
  FROM "static_cast<int>(std::floor(p.x - 0.5f + r))"
  TO "static_cast<int>(std::ceil(p.x + r)) + 1"
  FROM "static_cast<int>(std::ceil(p.y - 0.5f - r))"
  TO "static_cast<int>(std::floor(p.y - r)) - 1"
  FROM "static_cast<int>(std::floor(p.y - 0.5f + r))"
  TO "static_cast<int>(std::ceil(p.y + r)) + 1"
  FROM "const float weight = filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f))"
  TO "const float dx = p.x - (x + 0.5f), dy = p.y - (y + 0.5f)@SEMICOLON@
      if (std::fabs(dx) > r || std::fabs(dy) > r) continue@SEMICOLON@
      const float weight = filter.evaluate(dx, dy)"
  FROM "if (weight != 0.0f) film.addSample(x, y, weight, radiance)"
  TO "film.addSample(x, y, weight, radiance)")

# evaluate(dx, 0) = f(dx) f(0) and evaluate(0, dy) = f(0) f(dy), so their product over
# evaluate(0, 0) = f(0)^2 is f(dx) f(dy) = evaluate(dx, dy) (f(0) > 0 for every profile); only the
# float rounding differs. Column weights are computed once per sample instead of per pixel.
pathway_mutant(v_s1_splat_row_column_weights 1 stage1/stage1_filtering.cpp pass "splat precomputes 1D column and row weights and multiplies them (evaluate(dx,0)*evaluate(0,dy)/evaluate(0,0))"
  FROM "  for (int y = yFirst"
  TO "  const float centre = filter.evaluate(0.0f, 0.0f)@SEMICOLON@
  float columnWeight[2 * 8 + 3]@SEMICOLON@  // radius <= kMaxFilterRadius = 8: at most 17 columns
  for (int x = xFirst@SEMICOLON@ x <= xLast@SEMICOLON@ ++x) columnWeight[x - xFirst] = filter.evaluate(p.x - (x + 0.5f), 0.0f)@SEMICOLON@
  for (int y = yFirst"
  FROM "const float weight = filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f))"
  TO "const float weight = columnWeight[x - xFirst] * filter.evaluate(0.0f, p.y - (y + 0.5f)) / centre")

# Mitchell-Netravali's general form (1/6)[(12-9B-6C)|x|^3 + (-18+12B+6C)|x|^2 + (6-2B)] and
# (1/6)[(-B-6C)|x|^3 + (6B+30C)|x|^2 + (-12B-48C)|x| + (8B+24C)] with B = C = 1/3 gives exactly the
# README's coefficients (7, -12, 16/3 and -7/3, 12, -20, 32/3). The other profiles are the same
# functions written differently (equal values on the same supports).
pathway_mutant(v_s1_profiles_other_forms 1 stage1/stage1_filtering.cpp pass "profiles written otherwise: Mitchell from the general (B, C) cubic, Gaussian as exp(-(x/s)^2/2) cut at x^2 > 9s^2, tent/box by comparisons"
  FROM "float boxFilter(float x) {"
  TO "float boxFilter(float x) {
  return (x >= -0.5f && x <= 0.5f) ? 1.0f : 0.0f@SEMICOLON@
}

[[maybe_unused]] float referenceBoxFilter(float x) {"
  FROM "float tentFilter(float x) {"
  TO "float tentFilter(float x) {
  const float a = std::fabs(x)@SEMICOLON@
  if (a >= 1.0f) return 0.0f@SEMICOLON@
  return 1.0f - a@SEMICOLON@
}

[[maybe_unused]] float referenceTentFilter(float x) {"
  FROM "float mitchellNetravaliFilter(float x) {"
  TO "float mitchellNetravaliFilter(float x) {
  const float B = 1.0f / 3.0f, C = 1.0f / 3.0f@SEMICOLON@
  const float a = std::fabs(x)@SEMICOLON@
  if (a < 1.0f)
    return ((12.0f - 9.0f * B - 6.0f * C) * a * a * a + (-18.0f + 12.0f * B + 6.0f * C) * a * a +
            (6.0f - 2.0f * B)) / 6.0f@SEMICOLON@
  if (a <= 2.0f)
    return (((-B - 6.0f * C) * a + (6.0f * B + 30.0f * C)) * a + (-12.0f * B - 48.0f * C)) * a / 6.0f +
           (8.0f * B + 24.0f * C) / 6.0f@SEMICOLON@
  return 0.0f@SEMICOLON@
}

[[maybe_unused]] float referenceMitchellNetravaliFilter(float x) {"
  FROM "float gaussianFilter(float x, float sigma) {"
  TO "float gaussianFilter(float x, float sigma) {
  if (x * x > 9.0f * sigma * sigma) return 0.0f@SEMICOLON@
  const float t = x / sigma@SEMICOLON@
  return std::exp(-0.5f * t * t)@SEMICOLON@
}

[[maybe_unused]] float referenceGaussianFilter(float x, float sigma) {")

# A constant factor k on a profile scales the 2D filter by k^2 in both the numerator sum
# Σ f L and the denominator sum Σ f of every pixel, so the ratio the film computes is unchanged
# (README: "not normalised: the division takes care of it").
pathway_mutant(v_s1_gaussian_normalised 1 stage1/stage1_filtering.cpp pass "Gaussian normalised by 1/(sqrt(2 pi) sigma), Mitchell times 6 (the constant factors cancel)"
  FROM "return std::exp(-x * x / (2.0f * sigma * sigma))"
  TO "return std::exp(-x * x / (2.0f * sigma * sigma)) / (std::sqrt(2.0f * kPi) * sigma)"
  FROM "if (a < 1.0f) return (7.0f * a * a * a - 12.0f * a * a + 16.0f / 3.0f) / 6.0f"
  TO "if (a < 1.0f) return 7.0f * a * a * a - 12.0f * a * a + 16.0f / 3.0f"
  FROM "return (-7.0f / 3.0f * a * a * a + 12.0f * a * a - 20.0f * a + 32.0f / 3.0f) / 6.0f"
  TO "return -7.0f / 3.0f * a * a * a + 12.0f * a * a - 20.0f * a + 32.0f / 3.0f")

# The one-sample estimate g(w)/p(w) of AO = ∫ V cos/π dw is unbiased for any density p that
# is positive wherever g is: with p = 1/(2π) it is V cos θ / (π/(2π)) = 2 V cos θ, whose mean is AO.
# Noisier than cosine sampling (the estimate is no longer 0 or 1). sampleCosineHemisphere and its pdf
# (handed on to stages 3-5) are kept as the reference's.
pathway_mutant(v_s2_uniform_hemisphere 2 stage2/stage2_nested_ao.cpp pass "AO directions uniform on the hemisphere, divided by their pdf 1/(2 pi): estimate 2 V cos"
  FROM "float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,"
  TO "${PATHWAY_VARIANT_UNIFORM_HEMISPHERE}

${PATHWAY_VARIANT_UNIFORM_PDF}

float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,"
  FROM "const Vec3 local = sampleCosineHemisphere(u)"
  TO "const Vec3 local = sampleUniformHemisphere(u)"
  FROM "const float pdf = cosineHemispherePdf(local.z)"
  TO "const float pdf = uniformHemispherePdf(local.z)")

# The concentric map takes a uniform point of the square to a uniform point of the unit disk
# (it is area-preserving up to a constant); Malley's lift of any uniform disk point has density
# cos θ / π. Same density as the reference's, the numbers land elsewhere.
pathway_mutant(v_s2_concentric_disk 2 stage2/stage2_nested_ao.cpp pass "cosine sampling by Shirley-Chiu's concentric disk map instead of Malley's polar map"
  FROM "Vec3 sampleCosineHemisphere(Vec2 u) {"
  TO "${PATHWAY_VARIANT_CONCENTRIC_COSINE}

Vec3 sampleCosineHemisphere(Vec2 u) {
  return sampleConcentricCosine(u)@SEMICOLON@
}

[[maybe_unused]] Vec3 malleyPolarCosine(Vec2 u) {")

# Any orthonormal basis with z = n maps the density cos θ / π around +z to the same density
# around n (a rotation, possibly with a reflection, preserves solid angle and cos θ).
pathway_mutant(v_s2_gram_schmidt_basis 2 stage2/stage2_nested_ao.cpp pass "local-to-world with a Gram-Schmidt basis around the normal instead of Frame"
  FROM "float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,"
  TO "${PATHWAY_VARIANT_GRAM_SCHMIDT}

float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,"
  FROM "const Vec3 direction = Frame(hit.normal).toWorld(local)"
  TO "const Vec3 direction = gramSchmidtToWorld(hit.normal, local)")

# Frisvad's basis is orthonormal with z = n (see gram_schmidt). (u2, u1) is as uniform as
# (u1, u2), and 1 - u2 is uniform too, so r = sqrt(1 - u2), phi = 2π u1 still gives a uniform disk
# point and the density cos θ / π. cos θ recomputed as dot(direction, n) equals local.z up to
# rounding.
pathway_mutant(v_s2_frisvad_swapped_numbers 2 stage2/stage2_nested_ao.cpp pass "Frisvad's basis, the angle from u1 and the radius from u2 (r = sqrt(1 - u2)), cos from the world direction"
  FROM "Vec3 sampleCosineHemisphere(Vec2 u) {"
  TO "${PATHWAY_VARIANT_FRISVAD}

Vec3 sampleCosineHemisphere(Vec2 u) {
  const float r = std::sqrt(std::fmax(0.0f, 1.0f - u.y))@SEMICOLON@
  const float phi = 2.0f * kPi * u.x@SEMICOLON@
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(u.y))@SEMICOLON@
}

[[maybe_unused]] Vec3 malleyPolarCosine(Vec2 u) {"
  FROM "const Vec3 direction = Frame(hit.normal).toWorld(local)"
  TO "const Vec3 direction = frisvadToWorld(hit.normal, local)"
  FROM "return ambientOcclusionEstimate(blocked, local, pdf)"
  TO "return ambientOcclusionEstimate(blocked, Vec3(0.0f, 0.0f, glm::dot(direction, hit.normal)), pdf)")

# Ray j's first number is uniform in [j/M, (j+1)/M), so E[estimate_j] = M ∫ over that strip,
# and the average over the M rays is the integral over [0,1)^2: unbiased, less noise. Each ray
# still draws its own next2D() as the README asks.
pathway_mutant(v_s2_stratified_rays 2 stage2/stage2_nested_ao.cpp pass "the M AO rays of a hit stratified in u1: ray j uses ((j + u1)/M, u2)"
  FROM "sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_)"
  TO "{
        const Vec2 u = samples.next2D()@SEMICOLON@
        sum += ambientOcclusionSample(context, *hit, Vec2((j + u.x) / aoRays_, u.y), aoDistance_)@SEMICOLON@
      }")

# As v_s2_uniform_hemisphere: 2 V cos θ has mean AO under uniform directions; the basis is
# orthonormal with z = n. The pair is drawn where the reference draws it (dimensions 2-3, before
# the eye ray). Noisier than the reference. (Does not call stage2_.ambientOcclusionSample.)
pathway_mutant(v_s3_uniform_gram_schmidt 3 stage3/stage3_ao_4d.cpp pass "own AO estimate: uniform hemisphere directions over their pdf 1/(2 pi), Gram-Schmidt basis, still dimensions 2-3"
  FROM "#include \"render/stage_api.h\""
  TO "#include <cmath>

#include \"render/stage_api.h\""
  FROM "class AmbientOcclusion4D : public Integrator {"
  TO "${PATHWAY_VARIANT_UNIFORM_HEMISPHERE}

${PATHWAY_VARIANT_UNIFORM_PDF}

${PATHWAY_VARIANT_GRAM_SCHMIDT}

float uniformAmbientOcclusion(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                              float distance) {
  const Vec3 local = sampleUniformHemisphere(u)@SEMICOLON@
  const float pdf = uniformHemispherePdf(local.z)@SEMICOLON@
  if (pdf <= 0.0f) return 0.0f@SEMICOLON@
  const Ray ray = hit.spawnRay(gramSchmidtToWorld(hit.normal, local), distance)@SEMICOLON@
  const float visibility = context.occluded(ray, RayKind::Secondary) ? 0.0f : 1.0f@SEMICOLON@
  return visibility * local.z / (kPi * pdf)@SEMICOLON@
}

class AmbientOcclusion4D : public Integrator {"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return Color(uniformAmbientOcclusion(context, *hit, directionSample, aoDistance_))")

# Nothing is drawn after a miss, so every sample that uses the pair still gets dimensions
# 2-3: the same numbers go to the same place as in the reference (the README says so).
pathway_mutant(v_s3_pair_after_miss_test 3 stage3/stage3_ao_4d.cpp pass "the AO pair drawn after the miss test (README: same image in this stage)"
  FROM "const Vec2 directionSample = samples.next2D()"
  TO "(void)0"
  FROM "if (!hit) return context.background()"
  TO "if (!hit) return context.background()@SEMICOLON@
    const Vec2 directionSample = samples.next2D()")

# (u.y, u.x) is uniform on [0,1)^2 like (u.x, u.y), so the direction still has density
# cos θ / π; it still comes from dimensions 2-3 (jointly stratified with 0-1 under Sobol').
pathway_mutant(v_s3_swapped_pair 3 stage3/stage3_ao_4d.cpp pass "the AO pair used as (u3, u2): dimensions 2-3, in the other order"
  FROM "stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_)"
  TO "stage2_.ambientOcclusionSample(context, *hit, Vec2(directionSample.y, directionSample.x), aoDistance_)")

# Concentric map + Malley lift gives density cos θ / π (see v_s2_concentric_disk), Frisvad's
# basis is orthonormal with z = n; the estimate V cos θ / (π p) = V as in the reference.
pathway_mutant(v_s3_concentric_frisvad 3 stage3/stage3_ao_4d.cpp pass "own AO estimate: concentric-disk cosine sampling, Frisvad basis, V cos/(pi p)"
  FROM "#include \"render/stage_api.h\""
  TO "#include <cmath>

#include \"render/stage_api.h\""
  FROM "class AmbientOcclusion4D : public Integrator {"
  TO "${PATHWAY_VARIANT_CONCENTRIC_COSINE}

${PATHWAY_VARIANT_FRISVAD}

float concentricAmbientOcclusion(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                                 float distance) {
  const Vec3 local = sampleConcentricCosine(u)@SEMICOLON@
  const float pdf = local.z > 0.0f ? local.z * kInvPi : 0.0f@SEMICOLON@
  if (pdf <= 0.0f) return 0.0f@SEMICOLON@
  const Ray ray = hit.spawnRay(frisvadToWorld(hit.normal, local), distance)@SEMICOLON@
  const float visibility = context.occluded(ray, RayKind::Secondary) ? 0.0f : 1.0f@SEMICOLON@
  return visibility * local.z / (kPi * pdf)@SEMICOLON@
}

class AmbientOcclusion4D : public Integrator {"
  FROM "return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_))"
  TO "return Color(concentricAmbientOcclusion(context, *hit, directionSample, aoDistance_))")

# Each branch estimates ∫ (ρ/π) L cos dw by (ρ/π) L cos θ / p with p = 1/(2π) > 0 on the
# whole hemisphere: unbiased, noisier (the weight 2ρ cos θ varies).
pathway_mutant(v_s4_uniform_branches 4 stage4/stage4_naive_recursion.cpp pass "branch directions uniform on the hemisphere, divided by their pdf 1/(2 pi)"
  FROM "#include \"render/stage_api.h\""
  TO "#include <cmath>

#include \"render/stage_api.h\""
  FROM "class NaiveRecursion : public Integrator {"
  TO "${PATHWAY_VARIANT_UNIFORM_HEMISPHERE}

${PATHWAY_VARIANT_UNIFORM_PDF}

class NaiveRecursion : public Integrator {"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec3 local = sampleUniformHemisphere(samples.next2D())"
  FROM "const float pdf = stage2_.cosineHemispherePdf(local.z)"
  TO "const float pdf = uniformHemispherePdf(local.z)")

# Density cos θ / π (concentric + lift) around n with any orthonormal basis: same estimator
# as the reference; the numbers map to other directions.
pathway_mutant(v_s4_concentric_gram_schmidt 4 stage4/stage4_naive_recursion.cpp pass "own cosine sampling (concentric disk) and a Gram-Schmidt basis, cos from the world direction"
  FROM "#include \"render/stage_api.h\""
  TO "#include <cmath>

#include \"render/stage_api.h\""
  FROM "class NaiveRecursion : public Integrator {"
  TO "${PATHWAY_VARIANT_CONCENTRIC_COSINE}

${PATHWAY_VARIANT_GRAM_SCHMIDT}

class NaiveRecursion : public Integrator {"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec3 local = sampleConcentricCosine(samples.next2D())"
  FROM "const float pdf = stage2_.cosineHemispherePdf(local.z)"
  TO "const float pdf = local.z > 0.0f ? local.z * kInvPi : 0.0f"
  FROM "const Ray next = hit->spawnRay(frame.toWorld(local))"
  TO "const Vec3 direction = gramSchmidtToWorld(hit->normal, local)@SEMICOLON@
      (void)frame@SEMICOLON@
      const Ray next = hit->spawnRay(direction)"
  FROM "reflected += brdf * incoming * local.z / pdf"
  TO "reflected += brdf * incoming * glm::dot(direction, hit->normal) / pdf")

# Branch i's first number is uniform in [i/N, (i+1)/N): E[branch i] = N ∫ over that strip,
# and the average of the N branches is the full integral. Each branch still draws its own next2D().
pathway_mutant(v_s4_stratified_branches 4 stage4/stage4_naive_recursion.cpp pass "the N branches stratified in u1: branch i uses ((i + u1)/N, u2)"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec2 u = samples.next2D()@SEMICOLON@
      const Vec3 local = stage2_.sampleCosineHemisphere(Vec2((i + u.x) / branching_, u.y))")

# Only which dimension feeds which direction changes (the README does not fix it); each pair
# is still uniform and independent of the others under the independent sampler the stage-4
# cases use, so every branch has the reference's distribution.
pathway_mutant(v_s4_draw_all_then_recurse 4 stage4/stage4_naive_recursion.cpp pass "all N direction pairs of a hit drawn before any branch recurses (breadth-first numbers)"
  FROM "#include \"render/stage_api.h\""
  TO "#include <vector>

#include \"render/stage_api.h\""
  FROM "Color reflected(0.0f)"
  TO "Color reflected(0.0f)@SEMICOLON@
    std::vector<Vec2> pairs(static_cast<size_t>(branching_))@SEMICOLON@
    for (Vec2& u : pairs) u = samples.next2D()"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec3 local = stage2_.sampleCosineHemisphere(pairs[static_cast<size_t>(i)])")

# Any 0 < q <= 1 (possibly path-dependent, fixed before the roulette number) with survivors
# divided by q keeps the mean: q E[X]/q + (1-q) 0 = E[X]. A mean of 0 (black throughput) ends the
# path, which contributes 0 from there anyway. Same hits and numbers as the reference.
pathway_mutant(v_s5_roulette_mean_09 5 stage5/stage5_path_tracing.cpp pass "Russian roulette with q = min(0.9, mean of the throughput's components), weighted by 1/q"
  FROM "const float q = std::fmin(0.95f, maxComponent(throughput))"
  TO "const float q = std::fmin(0.9f, (throughput.x + throughput.y + throughput.z) / 3.0f)")

# Unbiased for any constant q in (0, 1] (see mean_09). Much noisier: survivors double their
# throughput. Roulette is played and its number drawn at exactly the reference's hits.
pathway_mutant(v_s5_roulette_half 5 stage5/stage5_path_tracing.cpp pass "Russian roulette with a constant q = 0.5 at the README's hits (bounce + 1 >= rr-depth), weighted by 1/q"
  FROM "const float q = std::fmin(0.95f, maxComponent(throughput))"
  TO "const float q = 0.5f")

# Unbiased as roulette_half. It plays roulette at other hits than the reference when rr-depth
# is not 3 (e.g. the course case with rr-depth 1), so its numbers differ from the reference's there;
# the README describes the reference's rule ("as the reference plays it") more than it requires it.
pathway_mutant(v_s5_roulette_half_from_bounce2 5 stage5/stage5_path_tracing.cpp pass "Russian roulette with q = 0.5 from the hit bounce 2 on, whatever rr-depth says, weighted by 1/q"
  FROM "if (bounce + 1 >= rouletteDepth_) {"
  TO "if (bounce >= 2) {"
  FROM "const float q = std::fmin(0.95f, maxComponent(throughput))"
  TO "const float q = 0.5f")

# Le brdf cos_x / (p_A d^2 / |cos_y|) = Le brdf cos_x |cos_y| / (d^2 p_A): the same value as
# the area form, written through the solid-angle density of the light point.
pathway_mutant(v_s5_nee_solid_angle 5 stage5/stage5_path_tracing.cpp pass "NEE in solid-angle form: pdf_w = p_A d^2 / |cos_y|, term Le brdf cos_x / pdf_w"
  FROM "const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared"
  TO "const float pdfSolidAngle = light.pdfArea * distanceSquared / std::fabs(cosLight)"
  FROM "light.emitter->emission * brdf * geometry / light.pdfArea"
  TO "light.emitter->emission * brdf * cosSurface / pdfSolidAngle")

# (u1, u2) uniform on the square, reflected through (1/2, 1/2) when above the diagonal, is
# uniform on the lower triangle; the affine map to the emitter keeps it uniform: density 1/area,
# times the pick's probability, as in the reference.
pathway_mutant(v_s5_triangle_fold 5 stage5/stage5_path_tracing.cpp pass "uniform point on the emitter by folding the unit square (u1 + u2 > 1 -> 1 - u), not s = sqrt(u1)"
  FROM "const float s = std::sqrt(uPoint.x)"
  TO "float a = uPoint.x, c = uPoint.y@SEMICOLON@
  if (a + c > 1.0f) {
    a = 1.0f - a@SEMICOLON@
    c = 1.0f - c@SEMICOLON@
  }"
  FROM "const float b0 = 1.0f - s, b1 = uPoint.y * s"
  TO "const float b1 = a, b2 = c"
  FROM "light.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2"
  TO "light.position = (1.0f - b1 - b2) * e.p0 + b1 * e.p1 + b2 * e.p2")

# One-sample estimate of ∫ brdf L cos dw with p = 1/(2π) > 0 everywhere on the hemisphere:
# unbiased; the roulette (unchanged rule) sees the new throughput. Noisier.
pathway_mutant(v_s5_uniform_continuation 5 stage5/stage5_path_tracing.cpp pass "continuation direction uniform on the hemisphere, throughput times brdf cos / (1/(2 pi)) = 2 rho cos"
  FROM "class PathTracer : public Integrator {"
  TO "${PATHWAY_VARIANT_UNIFORM_HEMISPHERE}

${PATHWAY_VARIANT_UNIFORM_PDF}

class PathTracer : public Integrator {"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec3 local = sampleUniformHemisphere(samples.next2D())"
  FROM "const float pdf = stage2_.cosineHemispherePdf(local.z)"
  TO "const float pdf = uniformHemispherePdf(local.z)")

# Density cos θ / π around n with another orthonormal basis: the reference's estimator, the
# numbers mapped to other directions.
pathway_mutant(v_s5_concentric_gram_schmidt 5 stage5/stage5_path_tracing.cpp pass "continuation by concentric-disk cosine sampling and a Gram-Schmidt basis"
  FROM "class PathTracer : public Integrator {"
  TO "${PATHWAY_VARIANT_CONCENTRIC_COSINE}

${PATHWAY_VARIANT_GRAM_SCHMIDT}

class PathTracer : public Integrator {"
  FROM "const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D())"
  TO "const Vec3 local = sampleConcentricCosine(samples.next2D())"
  FROM "const float pdf = stage2_.cosineHemispherePdf(local.z)"
  TO "const float pdf = local.z > 0.0f ? local.z * kInvPi : 0.0f"
  FROM "hit.spawnRay(Frame(hit.normal).toWorld(local))"
  TO "hit.spawnRay(gramSchmidtToWorld(hit.normal, local))")

# Multiple importance sampling (balance heuristic) of NEE and the emission a bounce ray finds:
# a path that reaches an emitter can come from either strategy, with densities per solid angle
# p_L = p_A d² / |cos_y| (the light sample) and p_B = cos_x / π (the cosine continuation); weights
# p_L / (p_L + p_B) and p_B / (p_L + p_B) add up to one for each path, so each light path is
# counted once. The emitter's pick probability comes from lights.pickOf(hit). The wavefront
# version (the reference's alone) is left out of this file.
pathway_mutant(v_s5_mis 5 stage5/stage5_path_tracing.cpp pass "multiple importance sampling of NEE and bounce emission (balance heuristic), with lights.pickOf"
  FROM "// The wavefront version, \"stage5@fast\""
  TO "#if 0  // this variant has no wavefront version
// The wavefront version, \"stage5@fast\""
  FROM "}  // namespace
}  // namespace pathway"
  TO "#endif
}  // namespace
}  // namespace pathway"
  FROM "Ray ray = cameraRay"
  TO "Vec3 previousNormal(0.0f)@SEMICOLON@
    Ray ray = cameraRay"
  FROM "if (addEmission) radiance += throughput * hit->emitted"
  TO "if (addEmission)
        radiance += throughput * hit->emitted@SEMICOLON@
      else
        radiance += throughput * hit->emitted * bounceWeight(*hit, ray, previousNormal)"
  FROM "ray = *next"
  TO "previousNormal = hit->normal@SEMICOLON@
      ray = *next"
  FROM "return DirectLight{shadowRay, light.emitter->emission * brdf * geometry / light.pdfArea}"
  TO "const float pLight = light.pdfArea * distanceSquared / std::fabs(cosLight)@SEMICOLON@
    const float pBounce = cosSurface * kInvPi@SEMICOLON@
    return DirectLight{shadowRay, light.emitter->emission * brdf * geometry / light.pdfArea *
                                      (pLight / (pLight + pBounce))}"
  FROM "  // Light arriving at `hit` straight from a point picked on the emitters, times the BRDF."
  TO "  // The balance heuristic's weight of emission that the ray from a hit with `previousNormal`
  // found at `hit`: p_B / (p_B + p_L), both per solid angle.
  float bounceWeight(const SurfaceHit& hit, const Ray& ray, const Vec3& previousNormal) const {
    const EmitterPicker::Pick pick = lights_.pickOf(hit)@SEMICOLON@
    if (!pick.emitter || pick.probability <= 0.0f) return 1.0f@SEMICOLON@  // NEE cannot find it
    const float length = glm::length(ray.direction)@SEMICOLON@
    const float distance = hit.distance * length@SEMICOLON@
    const float cosLight = std::fabs(glm::dot(hit.normal, ray.direction)) / length@SEMICOLON@
    const float cosBounce = std::fmax(0.0f, glm::dot(previousNormal, ray.direction) / length)@SEMICOLON@
    const float pBounce = cosBounce * kInvPi@SEMICOLON@
    const float pLight = pick.probability / pick.emitter->area * distance * distance / cosLight@SEMICOLON@
    return pBounce / (pBounce + pLight)@SEMICOLON@
  }

  // Light arriving at `hit` straight from a point picked on the emitters, times the BRDF.")

# Every emitting triangle equally likely, whatever light-pick says: a point on triangle k has
# density 1 / (count · area_k), its true density, so NEE stays unbiased (noisier where the
# emitters' power per area differs). light-pick only chooses the reference's rule.
pathway_mutant(v_s5_uniform_pick 5 stage5/stage5_path_tracing.cpp pass "emitters picked uniformly (1/count each), light-pick ignored, with that probability"
  FROM "class PathTracer : public Integrator {"
  TO "LightSample sampleUniformPick(const std::vector<EmissiveTriangle>& triangles, float uPick,
                              Vec2 uPoint) {
  const size_t count = triangles.size()@SEMICOLON@
  const size_t index = std::min(count - 1, static_cast<size_t>(uPick * static_cast<float>(count)))@SEMICOLON@
  const EmissiveTriangle& e = triangles[index]@SEMICOLON@
  const float s = std::sqrt(uPoint.x)@SEMICOLON@
  const float b0 = 1.0f - s, b1 = uPoint.y * s@SEMICOLON@
  LightSample light@SEMICOLON@
  light.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2@SEMICOLON@
  light.normal = e.normal@SEMICOLON@
  light.emitter = &e@SEMICOLON@
  light.pdfArea = 1.0f / (static_cast<float>(count) * e.area)@SEMICOLON@
  return light@SEMICOLON@
}

class PathTracer : public Integrator {"
  FROM "LightSample sampleLight(const EmitterPicker& lights"
  TO "[[maybe_unused]] LightSample sampleLight(const EmitterPicker& lights"
  FROM "lights_(setup.scene, setup.params.lightPick),"
  TO "lights_(setup.scene, setup.params.lightPick),
        triangles_(collectEmissiveTriangles(setup.scene)),"
  FROM "EmitterPicker lights_"
  TO "EmitterPicker lights_@SEMICOLON@
  std::vector<EmissiveTriangle> triangles_"
  FROM "const LightSample light = sampleLight(lights_, uPick, uPoint)"
  TO "const LightSample light = sampleUniformPick(triangles_, uPick, uPoint)")
