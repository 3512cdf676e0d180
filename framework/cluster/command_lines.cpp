#include "cluster/command_lines.h"

#include "engine/render_settings.h"
#include "render/integrator_registry.h"

namespace pathway {
namespace {

constexpr const char* kQuiet = "-q";

// A declared setting's option: "--spp".
std::string flag(const OptionSpec& setting) {
  return "--" + setting.name;
}

// A subcommand's first words: its name, and -q when quiet. (Word by word: a one-word initializer
// list followed by push_back draws a false -Warray-bounds from GCC 14.)
std::vector<std::string> subcommand(const char* name, bool quiet) {
  std::vector<std::string> words;
  words.push_back(name);
  if (quiet) words.push_back(kQuiet);
  return words;
}

void append(std::vector<std::string>& arguments, const std::vector<std::string>& more) {
  arguments.insert(arguments.end(), more.begin(), more.end());
}

}  // namespace

std::vector<std::string> RenderPartCommand::toArguments() const {
  std::vector<std::string> arguments = {"render"};
  append(arguments, renderArguments);
  append(arguments, {flag(setting::kSamplesPerPixel), std::to_string(spp), "--samples",
                     std::to_string(sampleBegin) + ":" + std::to_string(sampleEnd)});
  if (threads > 0) append(arguments, {flag(setting::kThreads), std::to_string(threads)});
  if (checkOnly) arguments.push_back("--check");
  if (quiet) arguments.push_back(kQuiet);
  append(arguments, {"-o", output});
  return arguments;
}

std::vector<std::string> MergeCommand::toArguments() const {
  std::vector<std::string> arguments = subcommand("merge", quiet);
  append(arguments, {flag(setting::kExposure), std::to_string(exposure)});
  append(arguments, parts);
  for (const std::string& output : outputs) append(arguments, {"-o", output});
  return arguments;
}

std::vector<std::string> GradeOptionsCheckCommand::toArguments() const {
  std::vector<std::string> arguments = {"grade", "--list-cases"};
  append(arguments, gradeArguments);
  return arguments;
}

std::vector<std::string> SubmissionGradeCommand::toArguments() const {
  std::vector<std::string> arguments = subcommand("grade", quiet);
  append(arguments, {"--submission", submission, "--output", output});
  append(arguments, gradeArguments);
  return arguments;
}

std::vector<std::string> ClassTableCommand::toArguments() const {
  std::vector<std::string> arguments = subcommand("grade", quiet);
  append(arguments, {"--submissions", submissions, "--output", output, "--table-only"});
  return arguments;
}

std::vector<std::string> withFastestReference(std::vector<std::string> arguments) {
  const std::string joined = "--integrator=";
  for (size_t i = 0; i < arguments.size(); ++i) {
    std::string& word = arguments[i];
    if ((word == "-i" || word == "--integrator") && i + 1 < arguments.size()) {
      arguments[i + 1] = referenceIntegratorFor(arguments[i + 1], ReferenceTracing::Fastest);
      ++i;
    } else if (word.rfind(joined, 0) == 0) {
      word = joined + referenceIntegratorFor(word.substr(joined.size()), ReferenceTracing::Fastest);
    } else if (word.size() > 2 && word.rfind("-i", 0) == 0) {  // -istage5@ref
      word = "-i" + referenceIntegratorFor(word.substr(2), ReferenceTracing::Fastest);
    }
  }
  return arguments;
}

}  // namespace pathway
