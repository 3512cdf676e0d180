// The sandbox (core/sandbox.h) on its own: the launcher's command line, a program run inside it
// (what it may and may not touch), and the processes a child leaves behind (core/child_process.h).
// tests/hostile_test.cpp attacks it the way a submission would.
#include "core/sandbox.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
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

// Under root the sandbox always becomes nobody (the grader stages what nobody must read), and the
// state it reports is read back from the process after the change: its real user.
TEST(Sandbox, RootAlwaysBecomesNobodyAndSaysSoFromInside) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root changes user";
  EXPECT_TRUE(sandboxUser().changes);
  if (!probeSandbox({}, SandboxMode::Auto).missing.empty())
    GTEST_SKIP() << "this kernel cannot shut a program in completely";
  SandboxedCommand command;
  command.program = {"/usr/bin/id", "-u"};
  std::string line = PATHWAY_BINARY;
  for (const std::string& word : command.toArguments()) line += " '" + word + "'";
  const test::CommandOutcome ran = test::runCommand(line);
  EXPECT_EQ(ran.exitCode, 0) << ran.output;
  EXPECT_EQ(ran.output, std::to_string(sandboxUser().uid) + "\n");
}

// Where no other user can be had (here: a user namespace that maps root alone, so uid 65534 does
// not exist in it), auto keeps root but drops every capability, and require refuses.
TEST(Sandbox, WhereNoOtherUserCanBeHadAutoDropsEveryCapabilityAndRequireRefuses) {
  if (test::runCommand("unshare --user --map-root-user true").exitCode != 0)
    GTEST_SKIP() << "no user namespaces here";
  if (!probeSandbox({}, SandboxMode::Auto).missing.empty())
    GTEST_SKIP() << "this kernel cannot shut a program in completely";
  SandboxedCommand command;
  command.program = {"/bin/grep", "-E", "^(Uid|CapEff|CapPrm|CapBnd)", "/proc/self/status"};
  const auto run = [&](SandboxMode mode) {
    command.mode = mode;
    std::string line = "unshare --user --map-root-user " + std::string(PATHWAY_BINARY);
    for (const std::string& word : command.toArguments()) line += " '" + word + "'";
    return test::runCommand(line);
  };
  const test::CommandOutcome kept = run(SandboxMode::Auto);
  EXPECT_EQ(kept.exitCode, 0) << kept.output;
  EXPECT_NE(kept.output.find("Uid:\t0\t"), std::string::npos) << kept.output;
  for (const char* set :
       {"CapEff:\t0000000000000000", "CapPrm:\t0000000000000000", "CapBnd:\t0000000000000000"})
    EXPECT_NE(kept.output.find(set), std::string::npos) << set << "\n" << kept.output;
  const test::CommandOutcome refused = run(SandboxMode::Require);
  EXPECT_NE(refused.exitCode, 0) << refused.output;
  EXPECT_NE(refused.output.find("--sandbox require runs student code as uid"), std::string::npos)
      << refused.output;
}

// A child starts clean: its own environment, /dev/null for input, and no descriptor of the
// grader's but its output; the folder it writes in is watched, and past its quota it is stopped.
TEST(ChildProcess, StartsWithNothingOfTheGradersButWhatItIsGiven) {
  const fs::path dir = test::freshTestFolder("pathway_clean_child");
  const fs::path secret = dir / "secret";
  std::ofstream(secret) << "the grader's\n";
  const int inherited = ::open(secret.c_str(), O_RDONLY);  // not close-on-exec
  ASSERT_GE(inherited, 0);
  ::setenv("PATHWAY_TEST_GRADER_TOKEN", "token-1234", 1);
  ChildOptions options;
  options.environment = untrustedChildEnvironment();
  const ChildOutcome outcome =
      runChild({"/bin/bash", "-c",
                "echo \"token=$PATHWAY_TEST_GRADER_TOKEN\"; cat <&" + std::to_string(inherited) +
                    " 2>&1 || echo closed; read -t 1 line && echo \"read=$line\" || echo no-input; "
                    "ls /proc/self/fd | tr '\\n' ' '"},
               30.0, (dir / "log").string(), options);
  ::close(inherited);
  ::unsetenv("PATHWAY_TEST_GRADER_TOKEN");
  EXPECT_TRUE(outcome.succeeded()) << outcome.output;
  EXPECT_NE(outcome.output.find("token=\n"), std::string::npos) << outcome.output;
  EXPECT_EQ(outcome.output.find("the grader's"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("closed"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("no-input"), std::string::npos) << outcome.output;
  // 0, 1, 2 and the descriptor ls reads /proc with: nothing else.
  const std::string descriptors = "\n0 1 2 3 ";
  ASSERT_GE(outcome.output.size(), descriptors.size());
  EXPECT_EQ(outcome.output.substr(outcome.output.size() - descriptors.size()), descriptors)
      << outcome.output;

  // 40 files of 1 MiB where 8 MiB are allowed: stopped, and said so.
  fs::create_directories(dir / "work");
  options.watchedFolder = (dir / "work").string();
  options.folderQuotaBytes = 8ull << 20;
  const ChildOutcome filling =
      runChild({"/bin/bash", "-c",
                "for i in $(seq 40); do head -c 1048576 /dev/zero > " + (dir / "work").string() +
                    "/f$i; sleep 0.05; done; echo all-written"},
               60.0, (dir / "log2").string(), options);
  EXPECT_TRUE(filling.overQuota) << filling.output;
  EXPECT_FALSE(filling.succeeded());
  EXPECT_EQ(filling.output.find("all-written"), std::string::npos) << filling.output;
  EXPECT_NE(filling.describe(60.0).find("wrote more than 8 MiB"), std::string::npos);
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
