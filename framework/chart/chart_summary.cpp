#include "chart/chart_summary.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "core/json_text.h"
#include "core/number_format.h"

namespace pathway {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The fit over the upper half of the spp exponents (at least the last two points): the
// asymptotic rate, not the start-up.
std::optional<LogLogFit> fitLine(const std::vector<ChartPoint>& points,
                                 const std::function<double(const ChartPoint&)>& x,
                                 const std::function<std::optional<double>(const ChartPoint&)>& y) {
  if (points.empty()) return std::nullopt;
  const uint32_t maxSpp = points.back().spp;
  const int k = static_cast<int>(std::lround(std::log2(double(maxSpp))));
  // At least the last two points, so that a short line still has a slope.
  const uint32_t fromSpp = std::min(1u << ((k + 1) / 2), std::max(1u, maxSpp / 2));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const ChartPoint& p : points) {
    if (p.spp < fromSpp || !y(p) || !(*y(p) > 0.0) || !(x(p) > 0.0)) continue;
    const double lx = std::log(x(p)), ly = std::log(*y(p));
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++n;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || !(std::abs(denominator) > 1e-12)) return std::nullopt;
  LogLogFit fit;
  fit.slope = (n * sxy - sx * sy) / denominator;
  fit.intercept = (sy - fit.slope * sx) / n;
  fit.fromSpp = fromSpp;
  fit.toSpp = maxSpp;
  return fit;
}

// y at `at` along the measured points, else from the fit. The points are taken in order of x:
// on a busy machine a render with more samples can take less time than the one before it.
std::optional<ReadOff> readOff(std::vector<ChartPoint> points, double at,
                               const std::function<double(const ChartPoint&)>& x,
                               const std::function<std::optional<double>(const ChartPoint&)>& y,
                               const std::optional<LogLogFit>& fit) {
  std::stable_sort(points.begin(), points.end(),
                   [&](const ChartPoint& a, const ChartPoint& b) { return x(a) < x(b); });
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const double x0 = x(points[i]), x1 = x(points[i + 1]);
    const auto y0 = y(points[i]), y1 = y(points[i + 1]);
    if (!y0 || !y1 || !(*y0 > 0.0) || !(*y1 > 0.0) || !(x0 > 0.0) || !(x1 >= x0)) continue;
    if (at < x0 || at > x1) continue;
    if (x1 == x0) return ReadOff{std::sqrt(*y0 * *y1), false};
    const double t = std::log(at / x0) / std::log(x1 / x0);
    return ReadOff{std::exp((1 - t) * std::log(*y0) + t * std::log(*y1)), false};
  }
  if (points.size() == 1 && x(points[0]) == at && y(points[0])) return ReadOff{*y(points[0])};
  if (!fit) return std::nullopt;
  return ReadOff{fit->at(at), true};
}

std::string number(double value) {
  return std::isfinite(value) ? formatNumber("%.6g", value) : "null";
}
// Three significant digits, for tables people read.
std::string brief(double value) {
  return formatNumber("%.3g", value);
}
std::string number(const std::optional<double>& value) {
  return value ? number(*value) : "null";
}
// A number, or null where there is none (jsonText writes NaN and infinities as null too).
Json jsonNumber(const std::optional<double>& value) {
  return value ? Json(*value) : Json(nullptr);
}
Json readOffJson(const std::optional<ReadOff>& value) {
  if (!value) return nullptr;
  return {
      {"value", value->value}, {"extrapolated", value->extrapolated}, {"at_most", value->atMost}};
}
Json fitJson(const std::optional<LogLogFit>& fit) {
  if (!fit) return nullptr;
  return {{"slope", fit->slope},
          {"intercept", fit->intercept},
          {"from_spp", fit->fromSpp},
          {"to_spp", fit->toSpp}};
}

}  // namespace

double LogLogFit::at(double x) const {
  return std::exp(intercept + slope * std::log(x));
}

ChartSummary summarizeChart(const ChartSpec& spec, const ChartData& data) {
  ChartSummary summary;
  summary.machine = data.machine;
  for (size_t c = 0; c < spec.configs.size(); ++c) {
    const ChartConfig& config = spec.configs[c];
    ChartLine line;
    line.config = &config;
    line.description = data.descriptions.at(c);
    for (const ChartReference& reference : data.references)
      if (reference.label == config.label) line.reference = &reference;
    double rays = 0.0, samples = 0.0;
    for (uint32_t spp = 1; spp <= spec.maxSppOf(config); spp *= 2) {
      std::vector<double> seconds, rayCounts, relMse, mse;
      for (const ChartRun& run : data.runs) {
        if (run.label != config.label || run.spp != spp) continue;
        seconds.push_back(run.seconds);
        rayCounts.push_back(double(run.counters.totalRays()));
        rays += double(run.counters.totalRays());
        samples += double(run.counters.samples);
        if (run.error) {
          relMse.push_back(run.error->relMse);
          mse.push_back(run.error->mse);
        }
      }
      if (seconds.empty()) continue;
      ChartPoint point;
      point.spp = spp;
      point.renders = static_cast<int>(seconds.size());
      point.seconds = median(seconds);
      point.secondsLow = *std::min_element(seconds.begin(), seconds.end());
      point.secondsHigh = *std::max_element(seconds.begin(), seconds.end());
      point.rays = median(rayCounts);
      if (!relMse.empty()) {
        point.relMse = median(relMse);
        point.relMseLow = *std::min_element(relMse.begin(), relMse.end());
        point.relMseHigh = *std::max_element(relMse.begin(), relMse.end());
        point.mse = median(mse);
        if (point.seconds > 0.0) point.efficiency = 1.0 / (*point.relMse * point.seconds);
      }
      line.points.push_back(point);
    }
    line.raysPerSample = samples > 0.0 ? rays / samples : 0.0;
    auto bySpp = [](const ChartPoint& p) { return double(p.spp); };
    auto bySeconds = [](const ChartPoint& p) { return p.seconds; };
    auto relMseOf = [](const ChartPoint& p) { return p.relMse; };
    auto mseOf = [](const ChartPoint& p) { return p.mse; };
    line.relMseBySpp = fitLine(line.points, bySpp, relMseOf);
    line.relMseBySeconds = fitLine(line.points, bySeconds, relMseOf);
    line.mseBySeconds = fitLine(line.points, bySeconds, mseOf);
    // Time to the target: where the measured line crosses it, else along the fit.
    for (size_t i = 0; i + 1 < line.points.size() && !line.secondsToTarget; ++i) {
      const ChartPoint &a = line.points[i], &b = line.points[i + 1];
      if (!a.relMse || !b.relMse || !(*a.relMse >= kTargetRelMse && *b.relMse <= kTargetRelMse))
        continue;
      if (*a.relMse == *b.relMse || !(a.seconds > 0.0 && b.seconds > 0.0)) continue;
      const double t = std::log(*a.relMse / kTargetRelMse) / std::log(*a.relMse / *b.relMse);
      line.secondsToTarget =
          ReadOff{std::exp((1 - t) * std::log(a.seconds) + t * std::log(b.seconds)), false};
    }
    const ChartPoint* first = line.points.empty() ? nullptr : &line.points.front();
    if (!line.secondsToTarget && first && first->relMse && *first->relMse <= kTargetRelMse)
      line.secondsToTarget = ReadOff{first->seconds, false, true};
    if (!line.secondsToTarget && line.relMseBySeconds &&
        line.relMseBySeconds->slope <= kSteepestUnextrapolatedSlope) {
      const LogLogFit& fit = *line.relMseBySeconds;
      line.secondsToTarget =
          ReadOff{std::exp((std::log(kTargetRelMse) - fit.intercept) / fit.slope), true};
    }
    summary.lines.push_back(std::move(line));
  }

  // Equal time and equal rays: the most that every line reached.
  if (!spec.withReference || summary.lines.empty()) return summary;
  summary.equalSeconds = summary.equalRays = INFINITY;
  for (const ChartLine& line : summary.lines) {
    if (line.points.empty()) continue;
    summary.equalSeconds = std::min(summary.equalSeconds, line.points.back().seconds);
    summary.equalRays = std::min(summary.equalRays, line.points.back().rays);
  }
  auto bySeconds = [](const ChartPoint& p) { return p.seconds; };
  auto byRays = [](const ChartPoint& p) { return p.rays; };
  auto relMseOf = [](const ChartPoint& p) { return p.relMse; };
  auto rmseOf = [](const ChartPoint& p) -> std::optional<double> {
    return p.mse ? std::optional<double>(std::sqrt(*p.mse)) : std::nullopt;
  };
  for (const ChartLine& line : summary.lines) {
    std::optional<LogLogFit> rmseFit;
    if (line.mseBySeconds) {  // √ of a power law is a power law with half the slope
      rmseFit = line.mseBySeconds;
      rmseFit->slope *= 0.5;
      rmseFit->intercept *= 0.5;
    }
    const std::optional<LogLogFit> raysFit = fitLine(line.points, byRays, relMseOf);
    const std::optional<LogLogFit> rmseRaysFit = fitLine(line.points, byRays, rmseOf);
    summary.relMseAtEqualSeconds.push_back(
        readOff(line.points, summary.equalSeconds, bySeconds, relMseOf, line.relMseBySeconds)
            .value_or(ReadOff{NAN, true}));
    summary.rmseAtEqualSeconds.push_back(
        readOff(line.points, summary.equalSeconds, bySeconds, rmseOf, rmseFit)
            .value_or(ReadOff{NAN, true}));
    summary.relMseAtEqualRays.push_back(
        readOff(line.points, summary.equalRays, byRays, relMseOf, raysFit)
            .value_or(ReadOff{NAN, true}));
    summary.rmseAtEqualRays.push_back(
        readOff(line.points, summary.equalRays, byRays, rmseOf, rmseRaysFit)
            .value_or(ReadOff{NAN, true}));
  }
  return summary;
}

std::string summaryJson(const ChartSpec& spec, const ChartSummary& summary) {
  Json lines = Json::array();
  for (size_t i = 0; i < summary.lines.size(); ++i) {
    const ChartLine& line = summary.lines[i];
    const ChartConfig& config = *line.config;
    Json reference = nullptr;
    if (line.reference)
      reference = {{"label", spec.referenceConfigOf(config).label},
                   {"spp", line.reference->spp},
                   {"exr", line.reference->exrPath},
                   {"png", line.reference->pngPath}};
    Json entry = {{"label", config.label},
                  {"integrator", config.choices.integrator},
                  {"description", line.description},
                  {"group", config.group},
                  {"x", jsonNumber(config.x)},
                  {"reference", reference},
                  {"rays_per_sample", line.raysPerSample},
                  {"fit_rel_mse_by_spp", fitJson(line.relMseBySpp)},
                  {"fit_rel_mse_by_seconds", fitJson(line.relMseBySeconds)},
                  {"fit_mse_by_seconds", fitJson(line.mseBySeconds)},
                  {"seconds_to_target", readOffJson(line.secondsToTarget)}};
    if (!summary.relMseAtEqualSeconds.empty()) {
      entry["rel_mse_at_equal_seconds"] = readOffJson(summary.relMseAtEqualSeconds[i]);
      entry["rmse_at_equal_seconds"] = readOffJson(summary.rmseAtEqualSeconds[i]);
      entry["rel_mse_at_equal_rays"] = readOffJson(summary.relMseAtEqualRays[i]);
      entry["rmse_at_equal_rays"] = readOffJson(summary.rmseAtEqualRays[i]);
    }
    Json points = Json::array();
    for (const ChartPoint& p : line.points)
      points.push_back({{"spp", p.spp},
                        {"renders", p.renders},
                        {"seconds", p.seconds},
                        {"seconds_low", p.secondsLow},
                        {"seconds_high", p.secondsHigh},
                        {"rays", p.rays},
                        {"rel_mse", jsonNumber(p.relMse)},
                        {"rel_mse_low", jsonNumber(p.relMseLow)},
                        {"rel_mse_high", jsonNumber(p.relMseHigh)},
                        {"mse", jsonNumber(p.mse)},
                        {"efficiency", jsonNumber(p.efficiency)}});
    entry["points"] = points;
    lines.push_back(entry);
  }
  const Json result = {{"title", spec.title},
                       {"machine", summary.machine},
                       {"target_rel_mse", kTargetRelMse},
                       {"rel_mse_epsilon", kRelMseEpsilon},
                       {"seeds", spec.seeds},
                       {"with_reference", spec.withReference},
                       {"equal_seconds", summary.equalSeconds},
                       {"equal_rays", summary.equalRays},
                       {"lines", lines}};
  return jsonText(result);
}

std::string summaryCsv(const ChartSummary& summary) {
  std::ostringstream out;
  out << "label,spp,renders,seconds_median,seconds_min,seconds_max,rays_median,rel_mse_median,"
         "rel_mse_min,rel_mse_max,rmse_median,efficiency\n";
  for (const ChartLine& line : summary.lines) {
    for (const ChartPoint& p : line.points) {
      std::string label = line.config->label;
      if (label.find_first_of(",\"") != std::string::npos) {
        std::string quoted = "\"";
        for (char c : label) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        label = quoted + "\"";
      }
      const auto blank = [](const std::string& s) { return s == "null" ? std::string() : s; };
      out << label << "," << p.spp << "," << p.renders << "," << number(p.seconds) << ","
          << number(p.secondsLow) << "," << number(p.secondsHigh) << "," << number(p.rays) << ","
          << blank(number(p.relMse)) << "," << blank(number(p.relMseLow)) << ","
          << blank(number(p.relMseHigh)) << "," << blank(p.mse ? number(std::sqrt(*p.mse)) : "null")
          << "," << blank(number(p.efficiency)) << "\n";
    }
  }
  return out.str();
}

std::string summaryMarkdown(const ChartSummary& summary) {
  std::ostringstream out;
  out << "Measured on " << summary.machine << ". relMSE = mean (x − r)² / (r² + " << kRelMseEpsilon
      << "); medians over seeds.\n\n";
  out << "| configuration | rays/sample | slope vs spp | slope vs s | relMSE at max spp | s at max "
         "spp | efficiency 1/(relMSE·s) | s to relMSE "
      << brief(kTargetRelMse) << " |";
  const bool equal = !summary.relMseAtEqualSeconds.empty();
  if (equal)
    out << " relMSE at " << brief(summary.equalSeconds) << " s | RMSE at "
        << brief(summary.equalSeconds) << " s |";
  out << "\n|---|---|---|---|---|---|---|---|" << (equal ? "---|---|" : "") << "\n";
  auto readOffText = [](const std::optional<ReadOff>& value) {
    if (!value || !std::isfinite(value->value)) return std::string("–");
    return (value->atMost ? "≤ " : "") + brief(value->value) +
           (value->extrapolated ? " (extrapolated)" : "");
  };
  for (size_t i = 0; i < summary.lines.size(); ++i) {
    const ChartLine& line = summary.lines[i];
    const ChartPoint* last = line.points.empty() ? nullptr : &line.points.back();
    out << "| " << line.config->label << " | " << brief(line.raysPerSample) << " | "
        << (line.relMseBySpp ? brief(line.relMseBySpp->slope) : "–") << " | "
        << (line.relMseBySeconds ? brief(line.relMseBySeconds->slope) : "–") << " | "
        << (last && last->relMse ? brief(*last->relMse) : "–") << " | "
        << (last ? brief(last->seconds) : "–") << " | "
        << (last && last->efficiency ? brief(*last->efficiency) : "–") << " | "
        << readOffText(line.secondsToTarget) << " |";
    if (equal)
      out << " " << readOffText(summary.relMseAtEqualSeconds[i]) << " | "
          << readOffText(summary.rmseAtEqualSeconds[i]) << " |";
    out << "\n";
  }
  return out.str();
}

}  // namespace pathway
