// The grader's diagnosis on images whose difference to the reference is known by construction:
// a factor, a half-pixel move, a blur, extra light in a masked region, one bright tile, more
// noise, and a difference of a shape no pattern has. Each must be named as what it is.
#include "grade/difference_diagnosis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "sampling/pcg32.h"

namespace pathway {
namespace {

constexpr int kSize = 64;
constexpr int kTile = 4;
constexpr int kReplicates = 64;
constexpr double kSigma = 0.02;  // one render's noise per pixel and channel
constexpr int kSubpixels = 8;    // per side, for the box-filtered images below

// The scene: a bright rectangle with hard edges on a gentle ramp.
double scene(double x, double y) {
  const bool inside = x > 20.3 && x < 44.6 && y > 18.2 && y < 40.7;
  return 0.2 + 0.3 * x / kSize + (inside ? 0.5 : 0.0);
}

// A region where "direct light" arrives: a soft blob, unrelated to the rectangle's edges.
double directMask(double x, double y) {
  const double dx = x - 16.0, dy = y - 46.0;
  return 0.4 * std::exp(-(dx * dx + dy * dy) / 120.0);
}

// The scene seen through pixels (a box filter), moved right by `shift` pixels.
Image boxFiltered(const std::function<double(double, double)>& f, double shift = 0.0) {
  Image image(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double sum = 0.0;
      for (int j = 0; j < kSubpixels; ++j)
        for (int i = 0; i < kSubpixels; ++i)
          sum += f(x + (i + 0.5) / kSubpixels - shift, y + (j + 0.5) / kSubpixels);
      image.at(x, y) = Color(static_cast<float>(sum / (kSubpixels * kSubpixels)));
    }
  return image;
}

Image withNoise(const Image& truth, uint64_t seed, double sigma = kSigma) {
  Pcg32 rng(seed);
  Image image = truth;
  for (Color& pixel : image.pixels)
    for (int c = 0; c < 3; ++c) {
      const double u1 = 1.0 - rng.nextFloat(), u2 = rng.nextFloat();
      pixel[c] +=
          static_cast<float>(sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2));
    }
  return image;
}

class Diagnosis : public ::testing::Test {
 protected:
  void SetUp() override {
    truth_ = boxFiltered(scene);
    std::vector<Image> replicates;
    for (int i = 0; i < kReplicates; ++i) replicates.push_back(withNoise(truth_, 100 + i));
    mean_ = Image(kSize, kSize);
    for (size_t p = 0; p < mean_.pixels.size(); ++p) {
      glm::dvec3 sum(0.0);
      for (const Image& r : replicates) sum += glm::dvec3(r.pixels[p]);
      mean_.pixels[p] = Color(sum / double(kReplicates));
    }
    tileVariance_ = replicateTileVariance(replicates, kTile);
    direct_ = boxFiltered(directMask);
  }

  pathway::Diagnosis diagnose(const Image& image, int stage = 0, bool nextEventEstimation = true) {
    ComparisonSettings settings;
    settings.tileSize = kTile;
    ComparisonInput compared;
    compared.image = &image;
    compared.reference = &mean_;
    compared.tileVariance = &tileVariance_;
    compared.replicates = kReplicates;
    const Comparison comparison = compareImages(compared, settings);
    EXPECT_FALSE(comparison.passed(settings)) << "the test's difference is too small to fail";
    DiagnosisInput input;
    input.image = &image;
    input.reference = &mean_;
    input.tileVariance = &tileVariance_;
    input.replicates = kReplicates;
    input.tileSize = kTile;
    input.stage = stage;
    input.nextEventEstimation = nextEventEstimation;
    input.patterns[pattern::kDirect] = &direct_;
    for (const auto& [name, image] : patterns_) input.patterns[name] = image;
    return diagnoseDifference(input, comparison, settings);
  }

  // The scene blurred: each pixel the mean of its four neighbours, itself counted twice.
  Image blurred() const {
    Image result = truth_;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        Color sum(0.0f);
        for (int d = -1; d <= 1; ++d)
          sum += truth_.at(std::clamp(x + d, 0, kSize - 1), y) +
                 truth_.at(x, std::clamp(y + d, 0, kSize - 1));
        result.at(x, y) = sum / 6.0f;
      }
    return result;
  }

  Image truth_, mean_, tileVariance_, direct_;
  std::map<std::string, const Image*> patterns_;  // more stored patterns, by name
};

TEST_F(Diagnosis, OneFactorIsScale) {
  Image image = truth_;
  for (Color& c : image.pixels) c *= 0.97f;
  const pathway::Diagnosis d = diagnose(withNoise(image, 7));
  EXPECT_EQ(d.cause, LikelyCause::Scale) << d.line();
  EXPECT_NE(d.explanation.find("% darker"), std::string::npos) << d.line();
}

TEST_F(Diagnosis, AHalfPixelMoveIsShift) {
  const pathway::Diagnosis d = diagnose(withNoise(boxFiltered(scene, 0.5), 7));
  EXPECT_EQ(d.cause, LikelyCause::Shift) << d.line();
  EXPECT_NE(d.explanation.find("moved by about (+0.50, +0.00)"), std::string::npos) << d.line();
}

TEST_F(Diagnosis, ABlurIsEdges) {
  const pathway::Diagnosis d = diagnose(withNoise(blurred(), 7));
  EXPECT_EQ(d.cause, LikelyCause::Edges) << d.line();
  EXPECT_NE(d.explanation.find("blurrier"), std::string::npos) << d.line();
}

TEST_F(Diagnosis, ExtraLightWhereTheDirectMaskIsIsLit) {
  Image image = truth_;
  for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += 0.2f * direct_.pixels[p];
  const pathway::Diagnosis d = diagnose(withNoise(image, 7));
  EXPECT_EQ(d.cause, LikelyCause::Lit) << d.line();
  EXPECT_NE(d.explanation.find("% too bright"), std::string::npos) << d.line();
  // Stage 5 points at next-event estimation, unless the case runs without it.
  const Image noisy = withNoise(image, 7);
  EXPECT_NE(diagnose(noisy, 5).explanation.find("look at next-event estimation"),
            std::string::npos);
  const pathway::Diagnosis withoutNee = diagnose(noisy, 5, false);
  EXPECT_EQ(withoutNee.cause, LikelyCause::Lit) << withoutNee.line();
  EXPECT_EQ(withoutNee.explanation.find("look at next-event estimation"), std::string::npos)
      << withoutNee.line();
  EXPECT_NE(withoutNee.explanation.find("runs without next-event estimation"), std::string::npos)
      << withoutNee.line();
}

TEST_F(Diagnosis, OcclusionSaysWhichWayAndHowFarInWordsThatAgree) {
  // AO with rays twice as long, minus the reference: darker in a soft region of its own.
  const Image longer = boxFiltered([](double x, double y) {
    const double dx = x - 44.0, dy = y - 20.0;
    return -0.4 * std::exp(-(dx * dx + dy * dy) / 100.0);
  });
  patterns_[pattern::kLongerRays] = &longer;
  const auto along = [&](double a) {
    Image image = truth_;
    for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += float(a) * longer.pixels[p];
    return diagnose(withNoise(image, 7), 2);
  };
  const pathway::Diagnosis further = along(0.5);  // half of the way to rays twice as long
  EXPECT_EQ(further.cause, LikelyCause::Occlusion) << further.line();
  EXPECT_NE(further.explanation.find("looks like AO with rays"), std::string::npos)
      << further.line();
  EXPECT_NE(further.explanation.find("% of the way there"), std::string::npos) << further.line();
  // The other way (brighter where longer rays darken): rays that stop short, never "0.00 of the
  // way there" to longer rays.
  const pathway::Diagnosis shorter = along(-0.5);
  EXPECT_EQ(shorter.cause, LikelyCause::Occlusion) << shorter.line();
  EXPECT_NE(shorter.explanation.find("the opposite way"), std::string::npos) << shorter.line();
  EXPECT_EQ(shorter.explanation.find("of the way there"), std::string::npos) << shorter.line();
  patterns_.erase(pattern::kLongerRays);
}

// Each message's direction follows from the measured difference, both ways.
TEST_F(Diagnosis, AFactorSaysBrighterOrDarkerAsMeasured) {
  for (const float factor : {0.97f, 1.03f}) {
    Image image = truth_;
    for (Color& c : image.pixels) c *= factor;
    const pathway::Diagnosis d = diagnose(withNoise(image, 7));
    EXPECT_EQ(d.cause, LikelyCause::Scale) << d.line();
    EXPECT_NE(d.explanation.find(factor > 1.0f ? "% brighter" : "% darker"), std::string::npos)
        << d.line();
  }
}

// +1 where a message says the image is wider or blurrier, -1 narrower or sharper ("about X times
// as wide": the sign of X - 1), 0 where it says neither.
int widthDirection(const std::string& text) {
  const bool wider =
      text.find("wider") != std::string::npos || text.find("blurrier") != std::string::npos;
  const bool narrower =
      text.find("narrower") != std::string::npos || text.find("sharper") != std::string::npos;
  if (wider != narrower) return wider ? 1 : -1;
  if (const size_t at = text.find(" times as wide"); at != std::string::npos) {
    const size_t start = text.rfind("about ", at);
    const double times = std::stod(text.substr(start + 6, at - start - 6));
    return times > 1.0 ? 1 : times < 1.0 ? -1 : 0;
  }
  return 0;
}

TEST_F(Diagnosis, EdgesSayWiderOrNarrowerAsMeasured) {
  // A filter's width as the stage 1 references store it: the image through a wider filter minus
  // a narrower one (here the scene blurred minus the scene sharpened, over each other's edges).
  const Image blur = blurred();
  Image wider = blur;
  for (size_t p = 0; p < wider.pixels.size(); ++p) {
    const Color sharpened = truth_.pixels[p] + 0.5f * (truth_.pixels[p] - blur.pixels[p]);
    wider.pixels[p] -= sharpened;
  }
  for (const bool withWidth : {false, true}) {
    if (withWidth) patterns_[pattern::kWiderFilter] = &wider;
    for (const float a : {-0.6f, 0.6f}) {
      Image image = truth_;
      for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += a * wider.pixels[p];
      const pathway::Diagnosis d = diagnose(withNoise(image, 7));
      EXPECT_EQ(d.cause, LikelyCause::Edges) << d.line();
      EXPECT_EQ(widthDirection(d.explanation), a > 0 ? 1 : -1) << d.line();
    }
  }
  patterns_.erase(pattern::kWiderFilter);
}

TEST_F(Diagnosis, LightSaysTooBrightOrTooDarkAsMeasured) {
  // Light after bounces in a region of its own (more of it: paths that go on too long; less:
  // paths that stop early).
  const Image indirect = boxFiltered([](double x, double y) {
    const double dx = x - 48.0, dy = y - 48.0;
    return 0.3 * std::exp(-(dx * dx + dy * dy) / 90.0);
  });
  patterns_[pattern::kIndirect] = &indirect;
  for (const auto& [mask, cause] :
       {std::pair<const Image*, LikelyCause>{&direct_, LikelyCause::Lit},
        {&indirect, LikelyCause::Indirect}})
    for (const float a : {-0.25f, 0.25f}) {
      Image image = truth_;
      for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += a * mask->pixels[p];
      const pathway::Diagnosis d = diagnose(withNoise(image, 7), 4);
      EXPECT_EQ(d.cause, cause) << d.line();
      EXPECT_NE(d.explanation.find(a > 0 ? "% too bright" : "% too dark"), std::string::npos)
          << d.line();
    }
  patterns_.erase(pattern::kIndirect);
}

// A soft blob of a colour of its own, centred at (cx, cy): where a mask below is.
Image colouredBlob(double cx, double cy, Color colour) {
  const Image grey = boxFiltered([cx, cy](double x, double y) {
    const double dx = x - cx, dy = y - cy;
    return std::exp(-(dx * dx + dy * dy) / 90.0);
  });
  Image image = grey;
  for (Color& pixel : image.pixels) pixel *= colour;
  return image;
}

TEST_F(Diagnosis, BackgroundLightSaysWhereAndWhichWayAsMeasured) {
  // The background seen by the camera, and its light on surfaces after bounces, each in a
  // region of its own; a background of another colour (grey for blue-grey) changes each
  // channel by a factor of its own.
  const Image escaped = colouredBlob(48.0, 14.0, Color(0.2f, 0.25f, 0.3f));
  const Image skyLit = colouredBlob(14.0, 20.0, Color(0.1f, 0.12f, 0.15f));
  patterns_[pattern::kEscaped] = &escaped;
  patterns_[pattern::kSkyLit] = &skyLit;
  Image grey = truth_;
  for (size_t p = 0; p < grey.pixels.size(); ++p)
    grey.pixels[p] += (Color(0.3f) / Color(0.2f, 0.25f, 0.3f) - 1.0f) * escaped.pixels[p];
  const pathway::Diagnosis d = diagnose(withNoise(grey, 7), 3);
  EXPECT_EQ(d.cause, LikelyCause::Background) << d.line();
  // Red 50% and green 20% too bright (blue right), within the noise.
  double red = 0.0, green = 0.0;
  const size_t at = d.explanation.find("another colour (red ");
  ASSERT_NE(at, std::string::npos) << d.line();
  int end = -1;  // set only when the text matches to the end of the format
  ASSERT_EQ(std::sscanf(d.explanation.c_str() + at,
                        "another colour (red %lf%% too bright, green %lf%% too bright%n", &red,
                        &green, &end),
            2)
      << d.line();
  EXPECT_GT(end, 0) << d.line();
  EXPECT_NEAR(red, 50.0, 5.0) << d.line();
  EXPECT_NEAR(green, 20.0, 5.0) << d.line();
  for (const float a : {-0.5f, 0.5f}) {
    Image image = truth_;
    for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += a * skyLit.pixels[p];
    const pathway::Diagnosis lit = diagnose(withNoise(image, 7), 5);
    EXPECT_EQ(lit.cause, LikelyCause::Background) << lit.line();
    EXPECT_NE(lit.explanation.find("reaches surfaces after a bounce"), std::string::npos)
        << lit.line();
    EXPECT_NE(lit.explanation.find(a > 0 ? "% too bright" : "% too dark"), std::string::npos)
        << lit.line();
  }
  patterns_.erase(pattern::kEscaped);
  patterns_.erase(pattern::kSkyLit);
}

TEST_F(Diagnosis, DeeperOrShallowerPathsSayWhichAsMeasured) {
  // What one bounce more adds, in a region of its own: a depth test off by one either way.
  const Image deeper = colouredBlob(46.0, 50.0, Color(0.15f));
  patterns_[pattern::kOneBounceMore] = &deeper;
  for (const float a : {-0.6f, 1.0f}) {
    Image image = truth_;
    for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += a * deeper.pixels[p];
    const pathway::Diagnosis d = diagnose(withNoise(image, 7), 4);
    EXPECT_EQ(d.cause, LikelyCause::Indirect) << d.line();
    EXPECT_NE(d.explanation.find(a > 0 ? "bounces past the depth" : "missing from the deepest"),
              std::string::npos)
        << d.line();
  }
  patterns_.erase(pattern::kOneBounceMore);
}

TEST_F(Diagnosis, ABlurAlongOneAxisSaysWhich) {
  // Each pixel the mean of itself (twice) and the pixels two away across, or down.
  for (const bool acrossOnly : {true, false}) {
    Image image = truth_;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const int dx = acrossOnly ? 2 : 0, dy = acrossOnly ? 0 : 2;
        image.at(x, y) =
            (2.0f * truth_.at(x, y) +
             truth_.at(std::clamp(x + dx, 0, kSize - 1), std::clamp(y + dy, 0, kSize - 1)) +
             truth_.at(std::clamp(x - dx, 0, kSize - 1), std::clamp(y - dy, 0, kSize - 1))) /
            4.0f;
      }
    const pathway::Diagnosis d = diagnose(withNoise(image, 7));
    EXPECT_EQ(d.cause, LikelyCause::Edges) << d.line();
    EXPECT_NE(d.explanation.find(acrossOnly ? "blurrier across and about as sharp down"
                                            : "about as sharp across and blurrier down"),
              std::string::npos)
        << d.line();
  }
}

TEST_F(Diagnosis, OneBrightTileIsLocal) {
  Image image = withNoise(truth_, 7);
  for (int y = 28; y < 32; ++y)
    for (int x = 8; x < 12; ++x) image.at(x, y) += Color(0.3f);
  const pathway::Diagnosis d = diagnose(image);
  EXPECT_EQ(d.cause, LikelyCause::Local) << d.line();
  EXPECT_NE(d.explanation.find("(8, 28)"), std::string::npos) << d.line();
}

TEST_F(Diagnosis, TwiceTheNoiseWithTheRightMeanIsNoise) {
  const pathway::Diagnosis d = diagnose(withNoise(truth_, 7, 2.0 * kSigma));
  EXPECT_EQ(d.cause, LikelyCause::Noise) << d.line();
}

TEST_F(Diagnosis, ADifferenceOfNoKnownShapeIsUnknown) {
  Image image = truth_;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      image.at(x, y) += Color(0.02f * static_cast<float>(std::sin(x * 0.1) * std::cos(y * 0.08)));
  const pathway::Diagnosis d = diagnose(withNoise(image, 7));
  EXPECT_EQ(d.cause, LikelyCause::Unknown) << d.line();
}

TEST_F(Diagnosis, NaNPixelsInOneTileAreLocal) {
  Image image = withNoise(truth_, 7);
  image.at(40, 9) = Color(NAN);
  const pathway::Diagnosis d = diagnose(image);
  EXPECT_EQ(d.cause, LikelyCause::Local) << d.line();
  EXPECT_NE(d.explanation.find("(40, 9)"), std::string::npos) << d.line();
}

TEST(LikelyCause, EveryCauseHasItsName) {
  EXPECT_STREQ(likelyCauseName(LikelyCause::Scale), "scale");
  EXPECT_STREQ(likelyCauseName(LikelyCause::Occlusion), "occlusion");
  EXPECT_STREQ(likelyCauseName(LikelyCause::Unknown), "unknown");
}

}  // namespace
}  // namespace pathway
