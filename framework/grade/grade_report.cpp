#include "grade/grade_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json_text.h"
#include "core/number_format.h"
#include "core/text_output.h"
#include "grade/statistics.h"
#include "io/image_io.h"

namespace pathway {

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

namespace fs = std::filesystem;

const Color kNegative(0.05f, 0.2f, 1.0f);
const Color kPositive(1.0f, 0.1f, 0.05f);
const Color kNeutral(1.0f, 1.0f, 1.0f);
const Color kOutline(1.0f, 0.85f, 0.0f);
const char* const kReportMarker = ".pathway-report";

Color diverging(double x) {  // x in [-1, 1]
  const float a = static_cast<float>(std::min(1.0, std::fabs(x)));
  return glm::mix(kNeutral, x < 0 ? kNegative : kPositive, a);
}

// p-values and other statistics, to three significant digits.
std::string statistic(double value) {
  return formatNumber("%.3g", value);
}

// Capped p-values (Bonferroni, Šidák) read "> 0.99", not "1".
std::string pValue(double p) {
  return p > kLargestShownP ? "&gt; " + statistic(kLargestShownP) : statistic(p);
}

const char* causeOf(const CaseResult& c) {
  return c.diagnosis ? likelyCauseName(c.diagnosis->cause) : "";
}

}  // namespace

std::string CaseResult::describe(const ComparisonSettings& settings) const {
  std::ostringstream out;
  out << (passed ? "PASSED" : "FAILED") << " (" << purpose << ")\n";
  if (!problem.empty()) out << problem << "\n";
  if (!note.empty()) out << note << "\n";
  for (const std::string& todo : todos) out << "unfinished code ran: TODO at " << todo << "\n";
  if (compared) out << comparison.describe(settings);
  if (diagnosis) out << diagnosis->line() << "\n";
  if (seconds > 0.0)
    out << "your render: " << formatNumber("%.2f", seconds) << " s, "
        << formatNumber("%.1f", raysPerSecond * 1e-6)
        << " M rays/s; the reference: " << formatNumber("%.2f", referenceSeconds) << " s, "
        << formatNumber("%.1f", referenceRaysPerSecond * 1e-6) << " M rays/s\n";
  return out.str();
}

// Points are whole hundredths (casePoints): summed as such, 6.67 + 6.67 + 6.66 is 20 exactly.
double GradeSummary::points() const {
  long hundredths = 0;
  for (const CaseResult& c : cases) hundredths += std::lround(100.0 * c.points);
  return hundredths / 100.0;
}

double GradeSummary::maxPoints() const {
  long hundredths = 0;
  for (const CaseResult& c : cases) hundredths += std::lround(100.0 * c.maxPoints);
  return hundredths / 100.0;
}

bool GradeSummary::passed() const {
  return std::all_of(cases.begin(), cases.end(), [](const CaseResult& c) { return c.passed; });
}

namespace {

// Each verdict's signed z (the channel farthest from 0) as colours, blue < 0 < red, saturating
// at `zFull`; failing ones outlined in yellow.
Image zMap(const std::vector<TileVerdict>& verdicts, int width, int height, double zFull) {
  Image map(width, height);
  for (const TileVerdict& tile : verdicts) {
    int channel = 0;
    for (int c = 1; c < 3; ++c)
      if (std::fabs(tile.z[c]) > std::fabs(tile.z[channel])) channel = c;
    const Color colour = diverging(tile.z[channel] / zFull);
    for (int y = tile.y0; y < tile.y1; ++y) {
      for (int x = tile.x0; x < tile.x1; ++x) {
        const bool edge = x == tile.x0 || y == tile.y0 || x == tile.x1 - 1 || y == tile.y1 - 1;
        map.at(x, y) = tile.failed && edge ? kOutline : colour;
      }
    }
  }
  return map;
}

}  // namespace

Image zHeatmap(const Comparison& comparison) {
  // Colours saturate at the |z| where a tile fails.
  const double zFail =
      comparison.tileThresholdP > 0.0 ? -normalQuantile(0.5 * comparison.tileThresholdP) : 5.0;
  return zMap(comparison.tiles, comparison.width, comparison.height, zFail);
}

Image blockZHeatmap(const Comparison& comparison) {
  return zMap(comparison.blocks, comparison.width, comparison.height, kBlockZFull);
}

Image differenceImage(const Image& image, const Image& reference) {
  Image result(image.width, image.height);
  if (image.width != reference.width || image.height != reference.height) return result;
  std::vector<double> differences(image.pixels.size());
  auto luminance = [](const Color& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
  for (size_t i = 0; i < image.pixels.size(); ++i)
    differences[i] = luminance(image.pixels[i]) - luminance(reference.pixels[i]);
  std::vector<double> magnitudes(differences.size());
  std::transform(differences.begin(), differences.end(), magnitudes.begin(),
                 [](double d) { return std::isfinite(d) ? std::fabs(d) : 0.0; });
  const size_t rank = magnitudes.size() * 99 / 100;
  std::nth_element(magnitudes.begin(), magnitudes.begin() + rank, magnitudes.end());
  const double scale = std::max(magnitudes[rank], 1e-12);
  for (size_t i = 0; i < differences.size(); ++i)
    result.pixels[i] = diverging(std::isfinite(differences[i]) ? differences[i] / scale : 0.0);
  return result;
}

namespace {

fs::path reportTarget(const std::string& folder) {
  fs::path target = fs::absolute(folder).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" is "out"
  return target;
}

}  // namespace

void checkReportFolder(const std::string& folder) {
  // The folder is replaced, so it must be one this program made (or a new one): never ".",
  // a home folder or a project that a mistyped --report names.
  const fs::path target = reportTarget(folder);
  if (target == target.root_path() || target.filename() == "..")
    throw PathwayError(folder + ": not a folder a report can replace");
  std::error_code error;
  if (fs::exists(target) && !fs::is_empty(target, error) && !fs::exists(target / kReportMarker))
    throw PathwayError(folder +
                       ": exists and is not a Pathway report folder, so it is not "
                       "replaced; choose another --report");
}

void writeHtmlReport(const std::string& folder, const GradeSummary& summary,
                     const ComparisonSettings& settings,
                     const std::map<std::string, std::string>& extraFiles) {
  checkReportFolder(folder);
  const fs::path target = reportTarget(folder);
  std::error_code error;
  const fs::path temporary = target.parent_path() / (".partial-" + target.filename().string());
  fs::remove_all(temporary, error);
  fs::create_directories(temporary / "images", error);
  if (error) throw PathwayError(folder + ": cannot create the report folder: " + error.message());
  std::ofstream(temporary / kReportMarker) << "written by pathway grade; replaced by the next\n";
  for (const auto& [name, content] : extraFiles) std::ofstream(temporary / name) << content;

  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<title>" << escapeHtml(summary.title) << "</title>\n<style>\n"
       << "body{font-family:sans-serif;margin:2em;max-width:80em;color:#222}\n"
       << "h2{margin-top:2em;border-bottom:1px solid #ccc}\n"
       << ".pass{color:#17692b}.fail{color:#b3261e}\n"
       << "figure{display:inline-block;margin:0 1em 1em 0;text-align:center}\n"
       << "figure img{width:240px;image-rendering:pixelated;border:1px solid #999}\n"
       << "table{border-collapse:collapse}td,th{padding:2px 10px;text-align:left}\n"
       << "pre{background:#f4f4f4;padding:.5em;white-space:pre-wrap}\n"
       << "</style></head><body>\n";
  page << "<h1>" << escapeHtml(summary.title) << "</h1>\n";
  page << "<p class=\"" << (summary.passed() ? "pass" : "fail") << "\"><b>"
       << formatNumber("%.1f", summary.points()) << " / "
       << formatNumber("%.1f", summary.maxPoints()) << " points</b>"
       << " &middot; " << summary.cases.size() << (summary.cases.size() == 1 ? " case" : " cases")
       << " &middot; graded in " << formatNumber("%.1f", summary.seconds) << " s</p>\n";
  for (const std::string& note : summary.notes) page << "<p>" << escapeHtml(note) << "</p>\n";
  if (!summary.sandbox.empty()) page << "<p>" << escapeHtml(summary.sandbox) << "</p>\n";
  page << "<table><tr><th>case</th><th>verdict</th><th>worst tile p</th><th>omnibus p</th>"
       << "<th>likely cause</th><th>your time</th><th>reference time</th></tr>\n";
  for (const CaseResult& c : summary.cases) {
    page << "<tr><td><a href=\"#" << escapeHtml(c.id) << "\">" << escapeHtml(c.title)
         << "</a></td><td class=\"" << (c.passed ? "pass\">pass" : "fail\">FAIL") << "</td><td>"
         << (c.compared && c.comparison.hardFailures.empty() ? pValue(c.comparison.worstTileP)
                                                             : "&ndash;")
         << "</td><td>"
         << (c.compared && c.comparison.hardFailures.empty() ? pValue(c.comparison.omnibusP)
                                                             : "&ndash;")
         << "</td><td>" << causeOf(c) << "</td><td>"
         << (c.seconds > 0 ? formatNumber("%.2f", c.seconds) + " s" : "&ndash;") << "</td><td>"
         << (c.referenceSeconds > 0 ? formatNumber("%.2f", c.referenceSeconds) + " s" : "&ndash;")
         << "</td></tr>\n";
  }
  page << "</table>\n";
  if (!summary.checks.empty()) {
    page
        << "<h2 id=\"checks\">Your sampling routines: warp tests (no points)</h2>\n"
        << "<p>Each draws many samples through a routine you wrote and tests them against the "
        << "density it claims (docs/warptest.md). A failure here says where a failing image's "
        << "bug may sit; <code>pathway warptest</code> shows it, with a picture for stage 2.</p>\n";
    for (const CaseResult& c : summary.checks)
      page << "<h3 id=\"" << escapeHtml(c.id) << "\">" << escapeHtml(c.title)
           << " &mdash; <span class=\"" << (c.passed ? "pass\">passed" : "fail\">failed")
           << "</span></h3>\n<pre>" << escapeHtml(c.describe(settings)) << "</pre>\n";
  }

  // Failing cases first, each with its maps and difference; a passing case shows its image beside
  // the reference's and no more (one render's noise against a mean of many would look like a
  // failure in a difference image).
  std::vector<const CaseResult*> ordered;
  for (const CaseResult& c : summary.cases)
    if (!c.passed) ordered.push_back(&c);
  for (const CaseResult& c : summary.cases)
    if (c.passed) ordered.push_back(&c);
  for (const CaseResult* shown : ordered) {
    const CaseResult& c = *shown;
    page << "<h2 id=\"" << escapeHtml(c.id) << "\">" << escapeHtml(c.title)
         << " &mdash; <span class=\"" << (c.passed ? "pass\">passed" : "fail\">failed")
         << "</span></h2>\n";
    if (c.compared && !c.image.pixels.empty()) {
      auto figure = [&](const std::string& name, const Image& image, const std::string& caption) {
        writePng((temporary / "images" / (c.id + "-" + name + ".png")).string(), image, 0.0f);
        page << "<figure><img src=\"images/" << escapeHtml(c.id) << "-" << name << ".png\" alt=\""
             << escapeHtml(caption) << "\"><figcaption>" << escapeHtml(caption)
             << "</figcaption></figure>\n";
      };
      figure("image", c.image, "yours");
      figure("reference", c.reference, "reference");
      if (!c.passed && !c.comparison.tiles.empty())
        figure("z", zHeatmap(c.comparison),
               "signed z per tile (blue: darker, red: brighter; yellow: failing)");
      if (!c.passed && !c.comparison.blocks.empty())
        figure("block-z", blockZHeatmap(c.comparison),
               "signed z per block of the whole-image tests (full colour at |z| = 3)");
      if (!c.passed && c.image.width == c.reference.width && c.image.height == c.reference.height)
        figure("difference", differenceImage(c.image, c.reference),
               "difference (yours − reference)");
    }
    page << "<pre>" << escapeHtml(c.describe(settings)) << "</pre>\n";
    if (c.compared && c.comparison.hardFailures.empty()) {
      const Comparison& k = c.comparison;
      page << "<table><tr><td>worst tile p (corrected)</td><td>" << pValue(k.worstTileP)
           << "</td></tr><tr><td>failing tiles</td><td>" << k.failingTiles << " of "
           << k.tiles.size() << "</td></tr><tr><td>omnibus p (corrected)</td><td>"
           << pValue(k.omnibusP) << "</td></tr><tr><td>&Sigma;z&sup2; p per channel</td><td>"
           << statistic(k.chiSquaredP[0]) << ", " << statistic(k.chiSquaredP[1]) << ", "
           << statistic(k.chiSquaredP[2]) << "</td></tr><tr><td>mean-shift p per channel</td><td>"
           << statistic(k.meanShiftP[0]) << ", " << statistic(k.meanShiftP[1]) << ", "
           << statistic(k.meanShiftP[2]) << "</td></tr><tr><td>NaN / infinite pixels</td><td>"
           << k.nonFinitePixels << "</td></tr><tr><td>degrees of freedom</td><td>"
           << statistic(k.degreesOfFreedom) << "</td></tr></table>\n";
    }
  }
  page << "</body></html>\n";
  {
    std::ofstream out(temporary / "index.html", std::ios::binary);
    out << page.str();
    if (!out.flush()) throw PathwayError(folder + ": writing the report failed");
  }
  // The old report moves aside before the new one moves in, so one of them is always whole.
  const fs::path old = target.parent_path() / (".old-" + target.filename().string());
  fs::remove_all(old, error);
  if (fs::exists(target)) fs::rename(target, old, error);
  if (!error) fs::rename(temporary, target, error);
  if (error) throw PathwayError(folder + ": could not move the finished report into place");
  fs::remove_all(old, error);
}

std::string gradescopeResults(const GradeSummary& summary, const ComparisonSettings& settings) {
  std::string overall = summary.title + "\n";
  for (const std::string& note : summary.notes) overall += note + "\n";
  if (!summary.sandbox.empty()) overall += summary.sandbox + "\n";
  // Points as the report shows them, to two decimals.
  auto points = [](double value) { return std::round(value * 100.0) / 100.0; };
  Json tests = Json::array();
  for (const CaseResult& c : summary.cases) {
    const char* image = !c.compared ? "none" : c.comparison.passed(settings) ? "pass" : "fail";
    tests.push_back({{"name", c.title},
                     {"score", points(c.points)},
                     {"max_score", points(c.maxPoints)},
                     {"status", c.passed ? "passed" : "failed"},
                     {"output", c.describe(settings)},
                     {"visibility", "visible"},
                     {"extra_data",
                      {{"image", image},
                       {"likely_cause", causeOf(c)},
                       {"todos", c.todos.size()},
                       // 0: not measured (stage 1, or no image to measure)
                       {"noise_ratio", c.compared ? c.comparison.noiseRatio : 0.0}}}});
  }
  for (const CaseResult& c : summary.checks)  // beside the cases, with no points
    tests.push_back({{"name", c.title},
                     {"score", 0.0},
                     {"max_score", 0.0},
                     {"status", c.passed ? "passed" : "failed"},
                     {"output", c.describe(settings)},
                     {"visibility", "visible"},
                     {"extra_data", {{"check", "warptest"}}}});
  const Json results = {{"score", points(summary.points())},
                        {"execution_time", std::round(summary.seconds * 10.0) / 10.0},
                        {"output", overall},
                        {"visibility", "visible"},
                        {"extra_data", {{"sandbox", summary.sandbox}}},
                        {"stdout_visibility", "hidden"},
                        {"tests", tests}};
  return jsonText(results);
}

void writeGradescopeResults(const std::string& path, const GradeSummary& summary,
                            const ComparisonSettings& settings) {
  writeTextAtomically(path, gradescopeResults(summary, settings));
}

}  // namespace pathway
