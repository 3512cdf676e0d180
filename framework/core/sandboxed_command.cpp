#include "core/sandboxed_command.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "core/error.h"

namespace pathway {
namespace {

// The launcher's options: written by toArguments, read by fromArguments, used nowhere else.
constexpr const char* kModeFlag = "--mode";           // once
constexpr const char* kReadFlag = "--read";           // per readable path
constexpr const char* kWriteFlag = "--write";         // per writable folder
constexpr const char* kMemoryFlag = "--memory";       // bytes of address space, once
constexpr const char* kCpuFlag = "--cpu";             // seconds of CPU time, once
constexpr const char* kFileSizeFlag = "--file-size";  // bytes, once
constexpr const char* kProgramMarker = "--";

PathwayError refusal(const std::string& problem) {
  return PathwayError(std::string(SandboxedCommand::kCommand) + ": " + problem);
}

}  // namespace

std::vector<std::string> SandboxedCommand::toArguments() const {
  std::vector<std::string> arguments = {kCommand, kModeFlag, sandboxModeName(mode)};
  for (const std::string& path : policy.readable)
    arguments.insert(arguments.end(), {kReadFlag, path});
  for (const std::string& path : policy.writable)
    arguments.insert(arguments.end(), {kWriteFlag, path});
  arguments.insert(arguments.end(), {kMemoryFlag, std::to_string(policy.addressSpaceBytes),
                                     kCpuFlag, std::to_string(policy.cpuSeconds), kFileSizeFlag,
                                     std::to_string(policy.fileBytes), kProgramMarker});
  arguments.insert(arguments.end(), program.begin(), program.end());
  return arguments;
}

SandboxedCommand SandboxedCommand::fromArguments(const std::vector<std::string>& arguments) {
  if (arguments.empty() || arguments.front() != kCommand)
    throw refusal("the command line does not start with " + std::string(kCommand));
  SandboxedCommand command;
  command.policy.startsPrograms = true;
  size_t i = 1;
  for (; i < arguments.size() && arguments[i] != kProgramMarker; ++i) {
    const std::string& flag = arguments[i];
    if (i + 1 == arguments.size()) throw refusal(flag + " needs a value");
    const std::string& value = arguments[++i];
    auto number = [&](uint64_t& target) {
      const char* end = value.data() + value.size();
      const std::from_chars_result read = std::from_chars(value.data(), end, target);
      if (value.empty() || read.ec != std::errc() || read.ptr != end)
        throw refusal(flag + " '" + value + "' is not a whole number");
    };
    if (flag == kModeFlag) {
      command.mode = parseSandboxMode(value);
    } else if (flag == kReadFlag) {
      command.policy.readable.push_back(value);
    } else if (flag == kWriteFlag) {
      command.policy.writable.push_back(value);
    } else if (flag == kMemoryFlag) {
      number(command.policy.addressSpaceBytes);
    } else if (flag == kCpuFlag) {
      number(command.policy.cpuSeconds);
    } else if (flag == kFileSizeFlag) {
      number(command.policy.fileBytes);
    } else {
      throw refusal("unknown argument '" + flag + "'");
    }
  }
  if (i + 1 >= arguments.size()) throw refusal("no program after " + std::string(kProgramMarker));
  command.program.assign(arguments.begin() + static_cast<long>(i) + 1, arguments.end());
  return command;
}

void runSandboxedCommand(const SandboxedCommand& command) {
  enterSandbox(command.policy, command.mode);
  if (!command.policy.writable.empty()) ::setenv("TMPDIR", command.policy.writable[0].c_str(), 1);
  std::vector<char*> argv;
  for (const std::string& word : command.program) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  ::execvp(argv[0], argv.data());
  throw PathwayError(command.program[0] +
                     " could not be started in the sandbox: " + std::strerror(errno));
}

}  // namespace pathway
