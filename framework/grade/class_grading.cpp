#include "grade/class_grading.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "core/error.h"
#include "grade/submission.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// "stage 2", "stages 2 and 4", "stages 1, 2 and 5".
std::string stageList(const std::set<int>& stages) {
  std::string text = stages.size() == 1 ? "stage " : "stages ";
  size_t i = 0;
  for (int stage : stages) {
    if (i > 0) text += i + 1 == stages.size() ? " and " : ", ";
    text += std::to_string(stage);
    ++i;
  }
  return text;
}

// The distinct likely causes of each stage's failing cases.
std::string likelyCauses(const GradeSummary& summary) {
  std::map<int, std::vector<std::string>> causes;
  for (const CaseResult& c : summary.cases) {
    if (!c.diagnosis) continue;
    std::vector<std::string>& list = causes[c.stage];
    const std::string name = likelyCauseName(c.diagnosis->cause);
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }
  std::string text;
  for (const auto& [stage, list] : causes) {
    text += (text.empty() ? "stage " : "; stage ") + std::to_string(stage) + ":";
    for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : " ") + list[i];
  }
  return text;
}

// Every case of the run failed for one reason (the submission did not build, a file is missing).
// The submission's name: its folder's, also for "alice/" and "./alice".
std::string submissionName(const std::string& folder) {
  fs::path path = fs::absolute(folder).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();
  return path.filename().string();
}

void failCases(GradeSummary& summary, const std::vector<const GradingCase*>& cases,
               const std::string& problem) {
  std::map<int, int> perStage, done;
  for (const GradingCase* c : cases) ++perStage[c->stage];
  for (const GradingCase* c : cases) {
    CaseResult result;
    result.id = c->id();
    result.title = "Stage " + std::to_string(c->stage) + " · " + c->name;
    result.purpose = c->purpose;
    result.stage = c->stage;
    result.problem = problem;
    result.maxPoints = casePoints(done[c->stage]++, perStage[c->stage]);
    summary.cases.push_back(std::move(result));
  }
}

constexpr const char* kRowFile = "submission.tsv";

// One line per field, "key<TAB>value"; the status on one line.
void writeRow(const fs::path& path, const SubmissionResult& row) {
  std::ofstream out(path);
  std::string status = row.status;
  std::replace_if(
      status.begin(), status.end(), [](char c) { return c == '\n' || c == '\t'; }, ' ');
  out << "name\t" << row.name << "\npoints\t" << row.points << "\nmaxPoints\t" << row.maxPoints
      << "\n";
  for (size_t stage = 0; stage < row.stagePoints.size(); ++stage)
    out << "stage" << stage + 1 << "\t" << row.stagePoints[stage] << "\n";
  out << "buildSeconds\t" << row.buildSeconds << "\ngradeSeconds\t" << row.gradeSeconds
      << "\nstatus\t" << status << "\ncauses\t" << row.causes << "\n";
}

bool readRow(const fs::path& path, SubmissionResult& row) {
  std::ifstream in(path);
  if (!in) return false;
  std::map<std::string, std::string> fields;
  for (std::string line; std::getline(in, line);) {
    const size_t tab = line.find('\t');
    if (tab != std::string::npos) fields[line.substr(0, tab)] = line.substr(tab + 1);
  }
  if (!fields.count("name") || !fields.count("status")) return false;
  row.name = fields["name"];
  row.points = std::atof(fields["points"].c_str());
  row.maxPoints = std::atof(fields["maxPoints"].c_str());
  row.stagePoints.assign(kStageCount, 0.0);
  for (int stage = 1; stage <= kStageCount; ++stage)
    row.stagePoints[stage - 1] = std::atof(fields["stage" + std::to_string(stage)].c_str());
  row.buildSeconds = std::atof(fields["buildSeconds"].c_str());
  row.gradeSeconds = std::atof(fields["gradeSeconds"].c_str());
  row.status = fields["status"];
  row.causes = fields["causes"];
  return true;
}

}  // namespace

StageFilesGrade gradeStageFiles(const std::string& folder, const std::string& buildFolder,
                                const GradingRun& gradingRun, double buildTimeLimit,
                                const ComparisonSettings& settings) {
  StageFilesGrade graded;
  GradeSummary& summary = graded.summary;
  Submission submission = findSubmission(folder);
  for (const std::string& file : submission.missing) summary.notes.push_back("missing: " + file);
  for (const std::string& file : submission.duplicates)
    summary.notes.push_back("a second copy, not used: " + file);
  for (const std::string& file : submission.ignored)
    summary.notes.push_back("not part of any stage, not compiled: " + file);
  // Only the stages graded are built.
  std::set<int> gradedStages;
  for (const GradingCase* c : gradingRun.cases) gradedStages.insert(c->stage);
  for (auto it = submission.files.begin(); it != submission.files.end();)
    it = gradedStages.count(it->first) ? std::next(it) : submission.files.erase(it);

  // Each stage file builds on its own: one that does not compile costs its own stage only.
  const SubmissionBuild build =
      buildSubmission(submission, buildFolder, buildTimeLimit, gradingRun.sandbox);
  graded.buildSeconds = build.seconds;
  GradingRun run = gradingRun;
  run.cases.clear();
  std::vector<const GradingCase*> missing;
  std::map<int, std::vector<const GradingCase*>> broken;
  for (const GradingCase* c : gradingRun.cases) {
    const auto built = build.stages.find(c->stage);
    if (built == build.stages.end())
      missing.push_back(c);
    else if (!built->second.succeeded)
      broken[c->stage].push_back(c);
    else
      run.cases.push_back(c);
  }
  for (const auto& [stage, result] : build.stages)
    if (result.succeeded) run.stageLibraries.push_back(result.library);
  const std::vector<std::string> notes = summary.notes;
  if (!run.cases.empty()) summary = gradeStages(run, settings);
  summary.notes = notes;
  summary.sandbox =
      build.sandbox + (summary.sandbox.empty() ? "" : "\nrenders: " + summary.sandbox);
  std::set<int> crashed, timedOut, uncompiled;
  for (const CaseResult& c : summary.cases) {
    if (c.crashed) crashed.insert(c.stage);
    if (c.timedOut) timedOut.insert(c.stage);
  }
  for (const auto& [stage, cases] : broken) {
    const StageBuild& failed = build.stages.at(stage);
    // The compiler's message once, for the whole stage; each case says where to find it.
    summary.notes.push_back("stage " + std::to_string(stage) + ": " + failed.problem + ":\n" +
                            failed.log);
    failCases(summary, cases,
              failed.problem + " (the compiler's message is at the top of the report)");
    uncompiled.insert(stage);
  }
  graded.status = "graded";
  if (!uncompiled.empty()) graded.status += "; " + stageList(uncompiled) + " did not compile";
  if (!crashed.empty()) graded.status += "; " + stageList(crashed) + " crashed";
  if (!timedOut.empty()) graded.status += "; " + stageList(timedOut) + " ran past the time limit";
  if (!missing.empty()) {
    failCases(summary, missing, "the stage's file is missing from the submission");
    std::set<int> stages;
    for (const GradingCase* c : missing) stages.insert(c->stage);
    graded.status += "; " + stageList(stages) + (stages.size() == 1 ? " is" : " are") + " missing";
  }
  std::stable_sort(summary.cases.begin(), summary.cases.end(),
                   [](const CaseResult& a, const CaseResult& b) { return a.stage < b.stage; });
  return graded;
}

SubmissionResult gradeSubmission(const std::string& folder, const std::string& output,
                                 const GradingRun& gradingRun, double buildTimeLimit,
                                 const ComparisonSettings& settings) {
  SubmissionResult row;
  row.name = submissionName(folder);
  const fs::path out(output);
  GradeSummary summary;
  try {
    fs::create_directories(out);
    StageFilesGrade graded =
        gradeStageFiles(folder, (out / "build").string(), gradingRun, buildTimeLimit, settings);
    summary = std::move(graded.summary);
    row.buildSeconds = graded.buildSeconds;
    row.gradeSeconds = summary.seconds;
    row.status = graded.status;
    row.causes = likelyCauses(summary);
  } catch (const std::exception& error) {
    // Never stops the others: the submission gets the reason, and no points.
    row.status = std::string("could not be graded: ") + error.what();
    summary.notes.push_back(row.status);
    failCases(summary, gradingRun.cases, row.status);
  }
  summary.title = summary.title.empty() ? "Pathway grading: " + row.name
                                        : summary.title + " (" + row.name + ")";
  writeGradescopeResults((out / "results.json").string(), summary, settings);
  writeHtmlReport((out / "report").string(), summary, settings);
  row.points = summary.points();
  row.maxPoints = summary.maxPoints();
  row.stagePoints.assign(kStageCount, 0.0);
  for (const CaseResult& c : summary.cases) row.stagePoints[c.stage - 1] += c.points;
  writeRow(out / kRowFile, row);
  return row;
}

namespace {

// A CSV field: quoted, quotes doubled (names like "Last, First" are common).
std::string csvField(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void writeClassTable(const ClassGrading& grading, const std::vector<SubmissionResult>& rows) {
  std::ofstream csv(fs::path(grading.output) / "class.csv");
  csv << "submission,points,max";
  for (int stage = 1; stage <= kStageCount; ++stage) csv << ",stage" << stage;
  csv << ",build_seconds,grade_seconds,status,likely_causes\n";
  std::ofstream html(fs::path(grading.output) / "index.html");
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Pathway: class "
          "grades</title>\n<style>body{font-family:sans-serif;margin:2em}"
          "td,th{padding:2px "
          "10px;text-align:right}td:first-child,th:first-child,td:nth-last-child(-n+2)"
          "{text-align:left}</style></head><body>\n<h1>Class grades</h1>\n<table><tr><th>"
          "submission</th><th>points</th>";
  for (int stage = 1; stage <= kStageCount; ++stage) html << "<th>stage " << stage << "</th>";
  html << "<th>build s</th><th>grade s</th><th>status</th><th>likely causes</th></tr>\n";
  for (const SubmissionResult& r : rows) {
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, "%.1f,%.1f", r.points, r.maxPoints);
    csv << csvField(r.name) << "," << numbers;
    const std::string name = escapeHtml(r.name);
    std::snprintf(numbers, sizeof numbers, "%.1f / %.1f", r.points, r.maxPoints);
    html << "<tr><td><a href=\"./" << name << "/report/index.html\">" << name << "</a></td><td>"
         << numbers << "</td>";
    for (double points : r.stagePoints) {
      std::snprintf(numbers, sizeof numbers, "%.1f", points);
      csv << "," << numbers;
      html << "<td>" << numbers << "</td>";
    }
    std::snprintf(numbers, sizeof numbers, "%.1f,%.1f", r.buildSeconds, r.gradeSeconds);
    csv << "," << numbers << "," << csvField(r.status) << "," << csvField(r.causes) << "\n";
    std::snprintf(numbers, sizeof numbers, "<td>%.1f</td><td>%.1f</td>", r.buildSeconds,
                  r.gradeSeconds);
    html << numbers << "<td>" << escapeHtml(r.status) << "</td><td>" << escapeHtml(r.causes)
         << "</td></tr>\n";
  }
  html << "</table></body></html>\n";
}

}  // namespace

std::vector<std::string> submissionFolders(const std::string& submissions) {
  if (!fs::is_directory(submissions))
    throw PathwayError(submissions + ": not a folder of submissions");
  std::vector<std::string> folders;
  for (const auto& entry : fs::directory_iterator(submissions))
    if (entry.is_directory()) folders.push_back(entry.path().string());
  std::sort(folders.begin(), folders.end());
  if (folders.empty()) throw PathwayError(submissions + ": holds no submission folders");
  return folders;
}

std::vector<SubmissionResult> readClassResults(const ClassGrading& grading) {
  std::vector<SubmissionResult> rows;
  for (const std::string& folder : submissionFolders(grading.submissions)) {
    const std::string name = submissionName(folder);
    SubmissionResult row;
    if (!readRow(fs::path(grading.output) / name / kRowFile, row)) {
      row = SubmissionResult{};
      row.name = name;
      row.stagePoints.assign(kStageCount, 0.0);
      row.status = "not graded: no results in " + (fs::path(grading.output) / name).string();
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<SubmissionResult> classTableFromResults(const ClassGrading& grading) {
  const std::vector<SubmissionResult> rows = readClassResults(grading);
  fs::create_directories(grading.output);
  writeClassTable(grading, rows);
  return rows;
}

std::vector<SubmissionResult> gradeClass(const ClassGrading& grading,
                                         const ComparisonSettings& settings) {
  const std::vector<std::string> folders = submissionFolders(grading.submissions);
  fs::create_directories(grading.output);
  std::vector<SubmissionResult> rows;
  for (const std::string& folder : folders) {
    if (grading.run.progress)
      std::fprintf(stderr, "== %s\n", fs::path(folder).filename().string().c_str());
    const std::string name = submissionName(folder);
    try {
      rows.push_back(gradeSubmission(folder, (fs::path(grading.output) / name).string(),
                                     grading.run, grading.buildTimeLimit, settings));
    } catch (const std::exception& error) {  // e.g. its results could not be written
      SubmissionResult row;
      row.name = name;
      row.stagePoints.assign(kStageCount, 0.0);
      row.status = std::string("could not be graded: ") + error.what();
      rows.push_back(row);
    }
    writeClassTable(grading, rows);  // the table so far, in case the run is stopped
  }
  return rows;
}

}  // namespace pathway
