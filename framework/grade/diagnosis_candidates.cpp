#include "grade/diagnosis_candidates.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/number_format.h"
#include "grade/difference_patterns.h"

namespace pathway {
namespace {

// Moves searched: up to kShiftSteps steps of 1/kShiftStepsPerPixel pixel each way.
constexpr int kShiftSteps = 4;
constexpr int kShiftStepsPerPixel = 4;

// Finite differences at pixel level, clamped at the borders.
Image derivative(const Image& r, const std::function<Color(const Image&, int, int)>& stencil) {
  Image out(r.width, r.height);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) out.at(x, y) = stencil(r, x, y);
  return out;
}

Color clamped(const Image& r, int x, int y) {
  return r.at(std::clamp(x, 0, r.width - 1), std::clamp(y, 0, r.height - 1));
}

Vector tileVector(const Image& image, const std::vector<TileBounds>& tiles) {
  Vector v;
  v.reserve(3 * tiles.size());
  for (const TileBounds& t : tiles) {
    const glm::dvec3 m = tileMean(image, t);
    v.insert(v.end(), {m.x, m.y, m.z});
  }
  return v;
}

}  // namespace

std::string percent(double fraction) {
  return formatNumber("%.1f%%", 100.0 * std::fabs(fraction));
}
std::string ratio(double value) {
  return formatNumber("%.2f", value);
}
std::string signedNumber(double value) {
  return formatNumber("%+.2f", value);
}

namespace {

// The reference moved right by sx and down by sy pixels (bilinear, clamped at the borders).
Image shifted(const Image& r, double sx, double sy) {
  Image out(r.width, r.height);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const double fx = x - sx, fy = y - sy;
      const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
      const float ax = static_cast<float>(fx - x0), ay = static_cast<float>(fy - y0);
      out.at(x, y) = (1 - ay) * ((1 - ax) * clamped(r, x0, y0) + ax * clamped(r, x0 + 1, y0)) +
                     ay * ((1 - ax) * clamped(r, x0, y0 + 1) + ax * clamped(r, x0 + 1, y0 + 1));
    }
  return out;
}

std::string movedBy(double sx, double sy) {
  return "the image is moved by about (" + signedNumber(sx) + ", " + signedNumber(sy) +
         ") pixels (right, down) against the reference: look at where a pixel's centre is and "
         "which pixels a sample reaches";
}

std::string brighterOrDarker(double coefficient) {
  return coefficient > 0 ? "too bright" : "too dark";
}

}  // namespace

std::vector<Candidate> candidates(const DiagnosisInput& input,
                                  const std::vector<TileBounds>& tiles) {
  const Image& r = *input.reference;
  std::vector<Candidate> list;
  list.push_back({LikelyCause::Scale, {tileVector(r, tiles)}, [](const std::vector<double>& c) {
                    return "the whole image is " + percent(c[0]) +
                           (c[0] > 0 ? " brighter" : " darker") +
                           " than the reference, by one factor: look for a constant that is "
                           "missing or extra, such as 1/pi, a cosine or a pdf";
                  }});
  const Image laplacian = derivative(r, [](const Image& i, int x, int y) {
    return clamped(i, x + 1, y) + clamped(i, x - 1, y) + clamped(i, x, y + 1) +
           clamped(i, x, y - 1) - 4.0f * i.at(x, y);
  });
  list.push_back(
      {LikelyCause::Edges, {tileVector(laplacian, tiles)}, [](const std::vector<double>& c) {
         // image ≈ R + a ∇²R: a > 0 spreads each edge (blur), a < 0 steepens it.
         return std::string("the differences sit at edges: the image is ") +
                (c[0] > 0 ? "blurrier" : "sharper") + " than the reference there; " + kFilterHint;
       }});
  // The same across and down apart: a filter that blurs (or sharpens) along one axis only.
  const Image across = derivative(r, [](const Image& i, int x, int y) {
    return clamped(i, x + 1, y) + clamped(i, x - 1, y) - 2.0f * i.at(x, y);
  });
  const Image down = derivative(r, [](const Image& i, int x, int y) {
    return clamped(i, x, y + 1) + clamped(i, x, y - 1) - 2.0f * i.at(x, y);
  });
  list.push_back(
      {LikelyCause::Edges,
       {tileVector(across, tiles), tileVector(down, tiles)},
       [](const std::vector<double>& c) {
         // An axis whose coefficient is under a quarter of the other's is called
         // unchanged: its sign is then mostly the other axis's leak at corners.
         const double larger = std::max(std::fabs(c[0]), std::fabs(c[1]));
         auto way = [larger](double a) {
           return std::fabs(a) < 0.25 * larger ? "about as sharp" : a > 0 ? "blurrier" : "sharper";
         };
         return std::string(
                    "the differences sit at edges, unlike across and down: "
                    "against the reference, the image is ") +
                way(c[0]) + " across and " + way(c[1]) + " down; " + kFilterHint;
       }});
  const Image dx = derivative(r, [](const Image& i, int x, int y) {
    return 0.5f * (clamped(i, x + 1, y) - clamped(i, x - 1, y));
  });
  const Image dy = derivative(r, [](const Image& i, int x, int y) {
    return 0.5f * (clamped(i, x, y + 1) - clamped(i, x, y - 1));
  });
  list.push_back({LikelyCause::Shift,
                  {tileVector(dx, tiles), tileVector(dy, tiles)},
                  [](const std::vector<double>& c) {
                    // image ≈ R + a·∇R = R(p + a): the image shows what the reference shows a
                    // further on, so it is moved by -a (to first order: it reads small moves across
                    // hard edges short).
                    return movedBy(-c[0], -c[1]);
                  }});
  // A move is searched on a grid of fractions of a pixel (a first-order fit of a gradient
  // misreads moves across hard edges); the search costs two more fitted numbers.
  for (int j = -kShiftSteps; j <= kShiftSteps; ++j)
    for (int i = -kShiftSteps; i <= kShiftSteps; ++i) {
      if (i == 0 && j == 0) continue;
      const double sx = double(i) / kShiftStepsPerPixel, sy = double(j) / kShiftStepsPerPixel;
      Image moved = shifted(r, sx, sy);
      for (size_t p = 0; p < moved.pixels.size(); ++p) moved.pixels[p] -= r.pixels[p];
      list.push_back({LikelyCause::Shift,
                      {tileVector(moved, tiles)},
                      [sx, sy](const std::vector<double>&) { return movedBy(sx, sy); },
                      2,
                      false});
    }
  const size_t fromImage = list.size();
  auto layer = [&](const char* name) -> const Image* {
    const auto it = input.patterns.find(name);
    return it != input.patterns.end() && it->second && it->second->width == r.width &&
                   it->second->height == r.height
               ? it->second
               : nullptr;
  };
  // Bounce rays that leave the scene return the background at every depth, so where there is
  // one, `direct` and each emitter's masks hold its light too: it is taken out of them below
  // (skyLitOnce: after one bounce; skyLit: after any number).
  const Image* skyLit = layer(pattern::kSkyLit);
  const Image* skyLitOnce = layer(pattern::kSkyLitOnce);
  const Image* indirect = layer(pattern::kIndirect);
  const Image* oneBounce = layer(pattern::kDirect);
  std::optional<Image> direct;  // light straight from the emitters
  if (oneBounce) direct = sumOfImages(*oneBounce, skyLitOnce, -1.0f);
  // Where a stage gathers light from the emitters: stage 5 samples them (NEE), stage 4 finds
  // them with its branches.
  const std::string gathering =
      input.stage == 4
          ? "look at the weight of a branch that reaches an emitter: the BRDF, cos theta, the "
            "pdf, the average over the N branches"
      : !input.nextEventEstimation
          ? "this case runs without next-event estimation, so look at a path that hits an "
            "emitter: the emission it adds, and the weight of the bounce that found it (BRDF, "
            "cos theta, pdf)"
          : "look at next-event estimation: how an emitter and a point on it are picked and "
            "their pdf, both cosines and the distance, the shadow ray, one-sided emitters";
  if (direct)
    list.push_back(
        {LikelyCause::Lit, {tileVector(*direct, tiles)}, [gathering](const std::vector<double>& c) {
           return "the differences are where light arrives straight from the "
                  "emitters (that light " +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) + "): " + gathering;
         }});
  if (oneBounce && indirect) {
    // Everything surfaces reflect (the background's light included, where there is one): a
    // weight wrong at every bounce (the BRDF, a cosine, the pdf) scales it all.
    const Image reflected = sumOfImages(*oneBounce, indirect);
    list.push_back(
        {LikelyCause::Lit,
         {tileVector(reflected, tiles)},
         [gathering](const std::vector<double>& c) {
           return "the differences are wherever surfaces reflect light, directly or after "
                  "bounces (" +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "), but not on the emitters themselves: " + gathering;
         }});
  }
  // Each emitter's own light, the background's taken out of each.
  for (const auto& [name, background] :
       {std::pair{pattern::directFrom, skyLitOnce}, std::pair{pattern::litFrom, skyLit}}) {
    std::vector<Vector> perEmitter;
    for (size_t k = 0; const Image* alone = layer(name(k).c_str()); ++k)
      perEmitter.push_back(tileVector(sumOfImages(*alone, background, -1.0f), tiles));
    if (perEmitter.size() < 2) continue;
    list.push_back({LikelyCause::Lit, perEmitter, [gathering](const std::vector<double>& c) {
                      std::string factors;
                      for (size_t k = 0; k < c.size(); ++k)
                        factors += (k ? ", " : "") + percent(c[k]) + " " + brighterOrDarker(c[k]);
                      return "the differences are where light from the emitters arrives, by a "
                             "factor of each emitter's own (" +
                             factors + "): " + gathering +
                             "; in particular whether an emitter's pdf is that of the rule that "
                             "picked it";
                    }});
  }
  if (indirect)
    list.push_back(
        {LikelyCause::Indirect, {tileVector(*indirect, tiles)}, [](const std::vector<double>& c) {
           return "the differences are in light that arrives after two or more "
                  "bounces (" +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "): look at the continuation ray and its weight, Russian "
                  "roulette's 1/q, and where paths stop";
         }});
  const Image* escaped = layer(pattern::kEscaped);
  if (escaped) {
    const Vector seen = tileVector(*escaped, tiles);
    list.push_back({LikelyCause::Background, {seen}, [](const std::vector<double>& c) {
                      return "the differences are where camera rays leave the scene (the "
                             "background " +
                             percent(c[0]) + " " + brighterOrDarker(c[0]) +
                             "): look at what a ray that hits nothing returns";
                    }});
    // A background of another colour: each channel off by a factor of its own.
    std::vector<Vector> channels(3, Vector(seen.size(), 0.0));
    for (size_t k = 0; k < seen.size(); ++k) channels[k % 3][k] = seen[k];
    list.push_back({LikelyCause::Background, channels, [](const std::vector<double>& c) {
                      return "the differences are where camera rays leave the scene, and the "
                             "background there has another colour (red " +
                             percent(c[0]) + " " + brighterOrDarker(c[0]) + ", green " +
                             percent(c[1]) + " " + brighterOrDarker(c[1]) + ", blue " +
                             percent(c[2]) + " " + brighterOrDarker(c[2]) +
                             "): look at what a ray that hits nothing returns, colour by colour";
                    }});
  }
  if (skyLit) {
    const std::string bounceRay =
        "look at what a bounce ray that leaves the scene returns, and the weight it is "
        "multiplied by";
    list.push_back({LikelyCause::Background,
                    {tileVector(*skyLit, tiles)},
                    [bounceRay](const std::vector<double>& c) {
                      return "the differences are where light from the background reaches "
                             "surfaces after a bounce (that light " +
                             percent(c[0]) + " " + brighterOrDarker(c[0]) + "): " + bounceRay;
                    }});
    if (escaped) {
      const Image everywhere = sumOfImages(*skyLit, escaped);
      list.push_back({LikelyCause::Background,
                      {tileVector(everywhere, tiles)},
                      [bounceRay](const std::vector<double>& c) {
                        return "the differences are wherever background light is seen, "
                               "directly or on surfaces (" +
                               percent(c[0]) + " " + brighterOrDarker(c[0]) +
                               "): look at the background's value, and " + bounceRay;
                      }});
    }
  }
  // Stage 5's continuation rays carry both light from the emitters after two or more bounces
  // and the background's light on surfaces; a weight wrong on them changes both.
  if (skyLitOnce && indirect) {
    const Image continued = sumOfImages(*indirect, skyLitOnce);
    list.push_back(
        {LikelyCause::Indirect, {tileVector(continued, tiles)}, [](const std::vector<double>& c) {
           return "the differences are in light that arrives after a bounce from "
                  "the background, or after two or more from the emitters (" +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "): look at the continuation ray and its weight, Russian "
                  "roulette's 1/q, and what a bounce ray that leaves the scene returns";
         }});
  }
  if (const Image* deeper = layer(pattern::kOneBounceMore))
    list.push_back(
        {LikelyCause::Indirect, {tileVector(*deeper, tiles)}, [](const std::vector<double>& c) {
           // image ≈ R + a (D - R), D the case one bounce deeper.
           return c[0] > 0.0
                      ? "the differences look like light from bounces past the depth the case "
                        "asks for (" +
                            percent(c[0]) +
                            " of one bounce more): look at the depth test, where paths stop, "
                            "and what counts as a bounce"
                      : "the differences look like light missing from the deepest bounces (" +
                            percent(c[0]) +
                            " of what one bounce more would add, taken away): look at the depth "
                            "test, where paths stop, Russian roulette's 1/q";
         }});
  if (const Image* occluded = layer(pattern::kOccluded))
    list.push_back(
        {LikelyCause::Occlusion, {tileVector(*occluded, tiles)}, [](const std::vector<double>& c) {
           // image ≈ R + a (U - R): the occluded part U - R shrinks by the factor a.
           return "the differences follow occlusion, in corners and near contacts "
                  "(the image there is " +
                  percent(c[0]) + (c[0] > 0 ? " less" : " more") +
                  " occluded than it should be): look at the AO ray's length, its "
                  "directions and their pdf, and where the ray starts";
         }});
  for (const auto& [name, rays] : {std::pair{pattern::kLongerRays, "twice as long"},
                                   std::pair{pattern::kUnlimitedRays, "of any length"}})
    if (const Image* longer = layer(name))
      list.push_back({LikelyCause::Occlusion,
                      {tileVector(*longer, tiles)},
                      [rays = std::string(rays)](const std::vector<double>& c) {
                        // image ≈ R + a (A' - R): a = 1 is AO with the longer rays, a < 0
                        // goes the other way (rays that stop short, or start off the surface).
                        if (c[0] < 0.0)
                          return "the differences follow occlusion, the opposite way to AO with "
                                 "rays " +
                                 rays + " (" + percent(c[0]) +
                                 " of that difference): AO rays that stop short or start too "
                                 "far from the surface; look at the AO ray's length (tMax), its "
                                 "start, and how they are passed on";
                        return "the differences follow occlusion: the image looks like AO with "
                               "rays " +
                               rays + ", " + percent(c[0]) +
                               " of the way there: look at the AO ray's length (tMax) and how "
                               "it is passed on";
                      }});
  // Half-pixel moves as rendered (not fitted: the move is the number searched).
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      if (const Image* moved = layer(pattern::movedByHalves(i, j).c_str()))
        list.push_back({LikelyCause::Shift,
                        {tileVector(*moved, tiles)},
                        [i, j](const std::vector<double>&) { return movedBy(0.5 * i, 0.5 * j); },
                        2,
                        false});
  const Image* movedRight = layer(pattern::kMovedRight);
  const Image* movedDown = layer(pattern::kMovedDown);
  if (movedRight && movedDown)
    list.push_back({LikelyCause::Shift,
                    {tileVector(*movedRight, tiles), tileVector(*movedDown, tiles)},
                    [](const std::vector<double>& c) { return movedBy(c[0], c[1]); }});
  if (const Image* wider = layer(pattern::kWiderFilter)) {
    // The filter's width and, beside it, the reference's Laplacian: a profile of another shape
    // moves light at edges as neither does alone.
    // Which way the fitted difference c0·W + c1·L goes: towards blurring (its overlap with the
    // Laplacian L > 0, which the wider filter W shares) or sharpening. Said only where it is
    // clear: one coefficient alone can point the other way when both patterns share the edges.
    const Vector widerTiles = tileVector(*wider, tiles),
                 laplacianTiles = tileVector(laplacian, tiles);
    double widerOnLaplacian = 0.0, laplacianSquared = 0.0;
    for (size_t k = 0; k < widerTiles.size(); ++k) {
      widerOnLaplacian += widerTiles[k] * laplacianTiles[k];
      laplacianSquared += laplacianTiles[k] * laplacianTiles[k];
    }
    list.push_back({LikelyCause::Edges,
                    {widerTiles, laplacianTiles},
                    [widerOnLaplacian, laplacianSquared](const std::vector<double>& c) {
                      const double blur = c[0] * widerOnLaplacian + c[1] * laplacianSquared;
                      return std::string(
                                 "the differences sit at edges: the filter's profile "
                                 "has another shape") +
                             (blur > 0   ? " (wider than it should be, in effect)"
                              : blur < 0 ? " (narrower than it should be, in effect)"
                                         : "") +
                             "; look at the filter's formula, its radius, and which pixels a "
                             "sample's splat reaches";
                    }});
    list.push_back(
        {LikelyCause::Edges, {tileVector(*wider, tiles)}, [](const std::vector<double>& c) {
           // 1.25 / 0.8 is e^0.446: a = 1 is a filter e^0.446 times as wide.
           return "the differences sit at edges: the image looks as if its filter were about " +
                  ratio(std::exp(0.446 * c[0])) + " times as wide as it should be; " + kFilterHint;
         }});
  }
  // A mask's light may be off by a factor that changes across the image (a pdf that is wrong for
  // one emitter, a cosine left out): the same mask times a smooth field, 1, u, v, u², uv, v² in
  // image coordinates, with its price in fitted numbers.
  const size_t rendered = list.size();
  for (size_t i = fromImage; i < rendered; ++i) {
    if (list[i].patterns.size() != 1 || list[i].cause == LikelyCause::Shift ||
        list[i].cause == LikelyCause::Edges)
      continue;
    Candidate modulated = list[i];
    const Vector base = modulated.patterns.front();
    for (int term = 1; term < 6; ++term) {
      Vector column(base.size());
      for (size_t k = 0; k < base.size(); ++k) {
        const TileBounds& t = tiles[k / 3];
        const double u = (t.x0 + t.x1) / double(r.width) - 1.0;
        const double v = (t.y0 + t.y1) / double(r.height) - 1.0;
        const double field[6] = {1.0, u, v, u * u, u * v, v * v};
        column[k] = base[k] * field[term];
      }
      modulated.patterns.push_back(std::move(column));
    }
    const auto explain = modulated.explain;
    modulated.explain = [explain](const std::vector<double>& c) {
      // The factor varies across the image: say its average (u and v run over [-1, 1], where u²
      // and v² average 1/3 and u, v, uv 0), not its constant term, which may be near 0.
      return explain({c[0] + (c[3] + c[5]) / 3.0}) + ", unevenly across the image";
    };
    list.push_back(std::move(modulated));
  }
  // The patterns rendered with the reference stages first: where one explains as much as a
  // pattern read off the reference image, it says more.
  std::rotate(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(fromImage), list.end());
  return list;
}

}  // namespace pathway
