// The sandbox (core/sandbox.h) on its own: the launcher's command line, a program run inside it
// (what it may and may not touch), and the processes a child leaves behind (core/child_process.h).
// tests/hostile_test.cpp attacks it the way a submission would.
#include "core/sandbox.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/child_process.h"
#include "core/error.h"
#include "core/sandboxed_command.h"
#include "run_command.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

SandboxedCommand sampleCommand() {
  SandboxedCommand command;
  command.mode = SandboxMode::Require;
  command.policy.startsPrograms = true;
  command.policy.readable = {"/srv/a course/framework", "/home/a student"};
  command.policy.writable = {"/tmp/a build"};
  command.policy.addressSpaceBytes = 4ull << 30;
  command.policy.cpuSeconds = 301;
  command.policy.fileBytes = 64ull << 20;
  command.program = {"c++", "-c", "stage 1.cpp", "--", "-o"};
  return command;
}

std::string refusal(const std::vector<std::string>& arguments) {
  try {
    SandboxedCommand::fromArguments(arguments);
  } catch (const PathwayError& error) {
    return error.what();
  }
  return "";
}

TEST(SandboxedCommand, ItsCommandLineReadsBackAsTheSameCommand) {
  const SandboxedCommand command = sampleCommand();
  const SandboxedCommand back = SandboxedCommand::fromArguments(command.toArguments());
  EXPECT_EQ(back.mode, command.mode);
  EXPECT_EQ(back.policy.readable, command.policy.readable);
  EXPECT_EQ(back.policy.writable, command.policy.writable);
  EXPECT_EQ(back.policy.addressSpaceBytes, command.policy.addressSpaceBytes);
  EXPECT_EQ(back.policy.cpuSeconds, command.policy.cpuSeconds);
  EXPECT_EQ(back.policy.fileBytes, command.policy.fileBytes);
  EXPECT_TRUE(back.policy.startsPrograms);
  EXPECT_EQ(back.program, command.program);  // its own "--" included
}

TEST(SandboxedCommand, AnythingElseIsRefusedNamingWhat) {
  const std::string name = SandboxedCommand::kCommand;
  EXPECT_EQ(refusal({name, "--mode", "auto", "--bogus", "x", "--", "ls"}),
            name + ": unknown argument '--bogus'");
  EXPECT_EQ(refusal({name, "--mode", "strict", "--", "ls"}),
            "unknown sandbox mode 'strict' (require, auto or off)");
  EXPECT_EQ(refusal({name, "--memory", "lots", "--", "ls"}),
            name + ": --memory 'lots' is not a whole number");
  EXPECT_EQ(refusal({name, "--mode", "auto"}), name + ": no program after --");
  EXPECT_EQ(refusal({"grade"}), name + ": the command line does not start with " + name);
}

TEST(Sandbox, ModesReadBackAndAnUnknownOneIsNamed) {
  for (SandboxMode mode : {SandboxMode::Require, SandboxMode::Auto, SandboxMode::Off})
    EXPECT_EQ(parseSandboxMode(sandboxModeName(mode)), mode);
  EXPECT_THROW(parseSandboxMode("on"), PathwayError);
  const SandboxState off = probeSandbox({}, SandboxMode::Off);
  EXPECT_EQ(off.summary(), "sandbox off: student code ran unconfined");
}

// A program in the sandbox reads the system and what the policy lists, writes only its folder,
// and reaches no network.
TEST(Sandbox, AProgramInsideReadsAndWritesOnlyWhatItsPolicySays) {
  if (!probeSandbox({}, SandboxMode::Auto).missing.empty())
    GTEST_SKIP() << "this kernel cannot shut a program in completely";
  const fs::path dir = test::freshTestFolder("pathway_sandbox");
  for (const char* folder : {"mine", "readable", "elsewhere"}) {
    fs::create_directories(dir / folder);
    fs::permissions(dir / folder, fs::perms::all);  // only the sandbox keeps it out
  }
  fs::permissions(dir, fs::perms::all);
  std::ofstream(dir / "readable/note") << "readable\n";
  std::ofstream(dir / "elsewhere/secret") << "not for the sandbox\n";
  fs::permissions(dir / "elsewhere/secret", fs::perms::all);
  SandboxedCommand command;
  command.policy.readable = {(dir / "readable").string()};
  command.policy.writable = {(dir / "mine").string()};
  shareWithSandboxUser((dir / "mine").string(), command.mode);
  // Without SHELL, bash looks its user up, and glibc tries nscd's local socket first: that
  // socket is refused, not punished.
  command.program = {"/usr/bin/env",
                     "-u",
                     "SHELL",
                     "/bin/bash",
                     "-c",
                     "cat " + (dir / "readable/note").string() + "; echo made > " +
                         (dir / "mine/made").string() + "; cat " +
                         (dir / "elsewhere/secret").string() + "; echo taken > " +
                         (dir / "elsewhere/taken").string() + "; echo \"tmp=$TMPDIR\"; exit 0"};
  std::string line = PATHWAY_BINARY;
  for (const std::string& word : command.toArguments()) line += " '" + word + "'";
  const test::CommandOutcome ran = test::runCommand(line);
  EXPECT_EQ(ran.exitCode, 0) << ran.output;
  EXPECT_NE(ran.output.find("readable"), std::string::npos) << ran.output;
  EXPECT_EQ(ran.output.find("not for the sandbox"), std::string::npos) << ran.output;
  EXPECT_NE(ran.output.find("tmp=" + (dir / "mine").string()), std::string::npos) << ran.output;
  EXPECT_TRUE(fs::exists(dir / "mine/made"));
  EXPECT_FALSE(fs::exists(dir / "elsewhere/taken"));

  // A socket kills it (a compiler never opens one).
  command.program = {"/bin/bash", "-c", "exec 3<>/dev/tcp/127.0.0.1/9; echo connected"};
  line = PATHWAY_BINARY;
  for (const std::string& word : command.toArguments()) line += " '" + word + "'";
  const test::CommandOutcome network = test::runCommand(line);
  EXPECT_NE(network.exitCode, 0) << network.output;
  EXPECT_EQ(network.output.find("connected"), std::string::npos) << network.output;
  fs::remove_all(dir);
}

bool markedProcessAlive(const std::string& marker) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream in(entry.path() / "cmdline");
    std::string arguments((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ifstream status(entry.path() / "status");
    std::string state;
    for (std::string line; std::getline(status, line);)
      if (line.rfind("State:", 0) == 0) state = line;
    if (arguments.find(marker) != std::string::npos && state.find('Z') == std::string::npos)
      return true;
  }
  return false;
}

// Under root the sandbox becomes nobody, unless nobody could not read what the policy lists
// (a clone in /root): then auto stays root and says so, and require refuses naming the path.
TEST(Sandbox, RootBecomesNobodyOnlyWhereNobodyCanRead) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root changes user";
  const fs::path dir = test::freshTestFolder("pathway_sandbox_user");
  fs::create_directories(dir / "open/inner");
  fs::create_directories(dir / "closed/inner");
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(dir / "closed", fs::perms::owner_all);
  SandboxPolicy open, closed;
  open.readable = {(dir / "open/inner").string()};
  closed.readable = {(dir / "closed/inner").string()};
  EXPECT_TRUE(sandboxUser(open).changes);
  const SandboxUser stays = sandboxUser(closed);
  EXPECT_FALSE(stays.changes);
  EXPECT_EQ(stays.staysRootFor, (dir / "closed/inner").string());
  if (probeSandbox({}, SandboxMode::Auto).missing.empty()) {
    EXPECT_NE(probeSandbox(closed, SandboxMode::Auto).summary().find("user: stays root"),
              std::string::npos);
    try {
      probeSandbox(closed, SandboxMode::Require);
      ADD_FAILURE() << "require ran as root";
    } catch (const PathwayError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("nobody, who cannot read " + (dir / "closed/inner").string()),
                std::string::npos)
          << error.what();
    }
  }
  fs::remove_all(dir);
}

TEST(ChildProcess, WhatAChildLeavesBehindIsEndedEvenInASessionOfItsOwn) {
  const std::string marker = "pathway-left-behind-" + std::to_string(::getpid());
  const fs::path log = test::freshTestFolder("pathway_left_behind") / "log";
  // One in the child's process group, one in a session of its own; the child exits at once.
  const ChildOutcome outcome =
      runChild({"/bin/bash", "-c",
                "(exec -a " + marker + " sleep 61) & setsid bash -c 'exec -a " + marker +
                    " sleep 62' & sleep 0.2; echo started"},
               30.0, log.string());
  EXPECT_TRUE(outcome.succeeded()) << outcome.output;
  EXPECT_GE(outcome.leftBehind, 1);
  EXPECT_FALSE(markedProcessAlive(marker));
  fs::remove_all(log.parent_path());
}

}  // namespace
}  // namespace pathway
