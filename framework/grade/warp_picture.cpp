#include "grade/warp_picture.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "grade/grade_report.h"
#include "io/image_io.h"
#include "io/raster_files.h"

namespace pathway {
namespace {

constexpr double kPanel = 240.0;  // each panel's side, in SVG units
constexpr double kGap = 30.0;
constexpr double kTop = 72.0;          // below the title and the verdict
constexpr double kResidualFull = 4.0;  // |O − E|/√E drawn at full colour

double panelLeft(int k) {
  return kGap + k * (kPanel + kGap);
}

// A dark-to-bright sequential scale (dark blue, teal, yellow) for counts in [0, 1].
std::string sequentialColour(double t) {
  static const double stops[][3] = {{0.07, 0.05, 0.33}, {0.13, 0.55, 0.55}, {0.99, 0.91, 0.14}};
  t = std::clamp(t, 0.0, 1.0) * 2.0;
  const int k = std::min(static_cast<int>(t), 1);
  const double f = t - k;
  char text[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<int>(std::lround(255.0 * ((1 - f) * stops[k][c] + f * stops[k + 1][c])));
  std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return text;
}

// Blue below 0, white at 0, red above, full at ±1.
std::string divergingColour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const int fade = static_cast<int>(std::lround(255.0 * (1.0 - std::fabs(t))));
  char text[8];
  if (t >= 0)
    std::snprintf(text, sizeof text, "#ff%02x%02x", fade, fade);
  else
    std::snprintf(text, sizeof text, "#%02x%02xff", fade, fade);
  return text;
}

// Cells as an image: φ across, cos θ down with the pole (cos θ = 1) on top.
template <typename Colour>
void drawCells(std::ostream& svg, const WarpTestResult& r, int panel, Colour colourOf) {
  const double w = kPanel / r.phiCells, h = kPanel / r.cosThetaCells;
  svg << "<g shape-rendering='crispEdges'>\n";
  for (int i = 0; i < r.cosThetaCells; ++i)
    for (int j = 0; j < r.phiCells; ++j) {
      const size_t cell = static_cast<size_t>(i) * r.phiCells + j;
      const double y = kTop + (r.cosThetaCells - 1 - i) * h;
      svg << "<rect x='" << panelLeft(panel) + j * w << "' y='" << y << "' width='" << w + 0.05
          << "' height='" << h + 0.05 << "' fill='" << colourOf(cell) << "'/>\n";
    }
  svg << "<rect x='" << panelLeft(panel) << "' y='" << kTop << "' width='" << kPanel << "' height='"
      << kPanel << "' fill='none' stroke='#444'/>\n";
  svg << "</g>\n";
}

void caption(std::ostream& svg, int panel, const std::string& first, const std::string& second) {
  const double x = panelLeft(panel) + kPanel / 2;
  svg << "<text x='" << x << "' y='" << kTop + kPanel + 20 << "' text-anchor='middle'>"
      << escapeHtml(first) << "</text>\n<text x='" << x << "' y='" << kTop + kPanel + 38
      << "' text-anchor='middle' class='small'>" << escapeHtml(second) << "</text>\n";
}

}  // namespace

std::string warpTestSvg(const WarpTestResult& r, const std::string& title) {
  const double width = 4 * kPanel + 5 * kGap, height = kTop + kPanel + 52;
  std::ostringstream svg;
  svg.precision(5);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
      << "' viewBox='0 0 " << width << ' ' << height << "' font-family='sans-serif' "
      << "font-size='13'>\n<style>.small{font-size:11px;fill:#555}</style>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n"
      << "<text x='" << kGap << "' y='20' font-weight='bold'>" << escapeHtml(title) << "</text>\n"
      << "<g fill='" << (r.passed ? "#1a7f37" : "#c62828") << "'>\n";
  // The verdict in two lines where it is long: what is wrong, then the statistic.
  const size_t statistic = r.verdict.find(": χ²");
  const bool split = statistic != std::string::npos && !r.passed;
  svg << "<text x='" << kGap << "' y='40'>"
      << escapeHtml(split ? r.verdict.substr(0, statistic) : r.verdict) << "</text>\n";
  if (split)
    svg << "<text x='" << kGap << "' y='58'>" << escapeHtml(r.verdict.substr(statistic + 2))
        << "</text>\n";
  svg << "</g>\n";

  // 1. The directions from above, by Lambert's equal-area projection (radius √(1 − cos θ)):
  // equal solid angles get equal areas, so uniform directions look uniform and a cosine-weighted
  // set thins out towards the rim; the pole is the centre.
  const double cx = panelLeft(0) + kPanel / 2, cy = kTop + kPanel / 2, radius = kPanel / 2;
  svg << "<circle cx='" << cx << "' cy='" << cy << "' r='" << radius
      << "' fill='#f4f4f4' stroke='#444'/>\n<g fill='#1f4e9c' fill-opacity='0.6'>\n";
  for (const Vec3& d : r.directions) {
    const double across = std::hypot(double(d.x), double(d.y));
    const double rho = std::sqrt(std::max(0.0, 1.0 - double(d.z)));
    const double x = across > 0 ? d.x / across : 0.0, y = across > 0 ? d.y / across : 0.0;
    svg << "<circle cx='" << cx + radius * rho * x << "' cy='" << cy - radius * rho * y
        << "' r='0.9'/>\n";
  }
  svg << "</g>\n";
  caption(svg, 0, "the first " + std::to_string(r.directions.size()) + " directions, from above",
          "equal-area: uniform looks uniform; pole at the centre");

  // 2 and 3. The histogram drawn and the one the pdf predicts, on one scale.
  double largest = 0.0;
  for (size_t c = 0; c < r.observed.size(); ++c)
    largest = std::max({largest, r.observed[c], r.expected[c]});
  const double scale = largest > 0 ? 1.0 / largest : 0.0;
  drawCells(svg, r, 1, [&](size_t c) { return sequentialColour(r.observed[c] * scale); });
  caption(svg, 1, "directions counted per cell", "across: φ; down: cos θ from 1 (pole) to 0");
  drawCells(svg, r, 2, [&](size_t c) { return sequentialColour(r.expected[c] * scale); });
  caption(svg, 2, "what your pdf predicts", "same cells, same colour scale");

  // 4. (O − E)/√E: about ±1 everywhere for a fit; a band or a ring where the warp or pdf is off.
  drawCells(svg, r, 3, [&](size_t c) {
    const double e = r.expected[c];
    const double z = e > 0 ? (r.observed[c] - e) / std::sqrt(e) : (r.observed[c] > 0 ? 1e9 : 0);
    return divergingColour(z / kResidualFull);
  });
  caption(svg, 3, "(counted − predicted) / √predicted",
          "red: too many, blue: too few; full colour at ±4");
  svg << "</svg>\n";
  return svg.str();
}

void writeWarpTestSvg(const std::string& path, const WarpTestResult& result,
                      const std::string& title) {
  if (lowerExtension(path) != ".svg")
    throw PathwayError("warp test picture '" + path + "': the file name must end in .svg");
  const std::string text = warpTestSvg(result, title);
  writeThroughTemporary(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw PathwayError(temporary + ": cannot write the warp test picture");
  });
}

}  // namespace pathway
