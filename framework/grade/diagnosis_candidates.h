// The likely cause's candidates (grade/difference_diagnosis.h): for each cause, the patterns a
// difference of that cause looks like (tile means of images made from the reference, or stored
// with it: masks and renderings of the reference stages) and how to say in words what the
// fitted coefficients mean. difference_diagnosis.cpp fits them and decides.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "grade/difference_diagnosis.h"
#include "grade/robust_fit.h"

namespace pathway {

// One candidate cause: its patterns (tile means, not yet whitened) and how to say what the
// fitted coefficients mean.
struct Candidate {
  LikelyCause cause;
  std::vector<Vector> patterns;
  std::function<std::string(const std::vector<double>&)> explain;
  int searchedNumbers = 0;  // numbers chosen by a search before the fit, each priced as fitted
  bool fitted = true;       // false: the pattern is the difference itself, coefficient 1
};

// Every candidate for this case, in the order the decision prefers on a tie: the patterns
// rendered with the reference stages first, then those read off the reference image.
std::vector<Candidate> candidates(const DiagnosisInput& input,
                                  const std::vector<TileBounds>& tiles);

// What the messages of several candidates point at, said once.
inline constexpr const char* kFilterHint =
    "look at the filter's profile and radius, and at which pixels a sample's splat reaches";
inline constexpr const char* kSamplingHint =
    "look at how samples are drawn (which dimensions, which directions for which pdf) or "
    "whether some are dropped";

// Numbers in messages: "12.3%" (of a fraction, unsigned), "1.25", "+0.50".
std::string percent(double fraction);
std::string ratio(double value);
std::string signedNumber(double value);

}  // namespace pathway
