// What the grader writes: an HTML report with pictures (viewable offline: the page and its PNGs
// in one folder) and Gradescope's results.json. Both are written to a temporary name and moved
// into place at the end, so a failed run leaves no partial report.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grade/difference_diagnosis.h"
#include "grade/image_comparison.h"

namespace pathway {

// The outcome of grading one case (or one pair of files).
struct CaseResult {
  std::string id;       // "stage3-cornell-box"
  std::string title;    // "Stage 3 · cornell-box"
  std::string purpose;  // what the case is there to catch
  int stage = 0;        // 0: a direct comparison of two files
  bool passed = false;
  std::string problem;  // set when the case could not be compared (crash, missing reference, ...)
  std::string note;     // how a failure was confirmed (or found to be chance); for two files,
                        // how their pixels differ
  bool crashed = false, timedOut = false;
  std::vector<std::string> todos;  // unfinished stage code that ran ("file:line")
  bool compared = false;           // `comparison` and the images below are filled in
  Comparison comparison;
  // What kind of bug the failing image shows; only for an image that was compared and failed.
  std::optional<Diagnosis> diagnosis;
  Image image, reference;
  double seconds = 0.0, raysPerSecond = 0.0;                    // the submission's render
  double referenceSeconds = 0.0, referenceRaysPerSecond = 0.0;  // one reference replicate
  double points = 0.0, maxPoints = 0.0;

  // The text a student reads for this case: verdict, reason, numbers, timing.
  std::string describe(const ComparisonSettings& settings) const;
};

struct GradeSummary {
  std::string title;  // "Pathway grading: each stage on the reference's earlier stages"
  std::vector<CaseResult> cases;
  // Checks beside the cases, with no points: the warp tests of the stages' sampling routines
  // (docs/warptest.md). They say where a failing image's bug may sit; points(), maxPoints() and
  // passed() count the cases alone.
  std::vector<CaseResult> checks;
  std::vector<std::string> notes;  // submission-wide remarks (missing files, build output, ...)
  std::string sandbox;  // how student code was shut in while it ran (SandboxState::summary)
  double seconds = 0.0;

  double points() const;
  double maxPoints() const;
  bool passed() const;
};

// Throws PathwayError unless `folder` is new, empty or a report this program wrote (it is
// replaced as a whole): checked before grading starts.
void checkReportFolder(const std::string& folder);
// `folder`/index.html, `folder`/images/*.png and `extraFiles` (name -> content, e.g.
// results.json), all moved into place together; the previous report is replaced.
void writeHtmlReport(const std::string& folder, const GradeSummary& summary,
                     const ComparisonSettings& settings,
                     const std::map<std::string, std::string>& extraFiles = {});
// Gradescope's format: one test per case with score, max_score, status, output, visibility.
std::string gradescopeResults(const GradeSummary& summary, const ComparisonSettings& settings);
void writeGradescopeResults(const std::string& path, const GradeSummary& summary,
                            const ComparisonSettings& settings);

// Text made safe for HTML (& < > ").
std::string escapeHtml(const std::string& text);

// The signed z of each tile (the channel farthest from 0) as colours, blue < 0 < red, saturating
// at the failure threshold, with failing tiles outlined in yellow. Linear RGB, image-sized.
Image zHeatmap(const Comparison& comparison);
// The same for the whole-image tests' blocks, saturating at |z| = kBlockZFull and never outlined:
// it shows a difference spread too thinly for any tile to fail.
constexpr double kBlockZFull = 3.0;
Image blockZHeatmap(const Comparison& comparison);
// image - reference in luminance, blue < 0 < red, scaled so the 99th percentile of |difference| is
// full colour. Linear RGB.
Image differenceImage(const Image& image, const Image& reference);

}  // namespace pathway
