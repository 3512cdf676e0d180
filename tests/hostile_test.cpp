// The hostile-submission suite (tests/hostile/): stage files that attack the grader instead of
// doing the work or to hurt a classmate. Each must end in failed cases or a refused load with a
// clear message, and leave nothing outside the grader's own folders changed, no process, no
// System V object and no harmed neighbour behind, and no secret of the grader's in the results.
// Where an attack has an effect to see, it is run once more with --sandbox off, as a control:
// there it works (loot copied out, a file written, a connection made, processes started, IPC
// left behind, a neighbour's limit changed, a secret printed, the disk filled), which shows the
// sandbox is what stops it. The forged kits' control is a process that holds the reference; two
// students in one class run are graded together. A stage with the shipped references baked into
// its source fails too: as too close to the references on the shipped cases, and on the course's
// own cases.
#include <arpa/inet.h>
#include <dlfcn.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/resource.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/sandbox.h"
#include "grade/grading_cases.h"
#include "grade/grading_reference.h"
#include "grade_results.h"
#include "render/integrator_registry.h"
#include "render/stage_kit.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// The folder the attacks and this test agree on (tests/hostile/hostile_kit.h).
const fs::path kWork = PATHWAY_HOSTILE_WORK;
constexpr int kSharedKey = 0x50617468, kQueueKey = 0x50617469, kSemaphoreKey = 0x5061746a;
constexpr rlim_t kVictimFileLimit = 123456789;
constexpr const char* kSecretVariable = "PATHWAY_HOSTILE_GRADER_TOKEN";
constexpr const char* kToken = "token-5f3a9c";

struct Hostile {
  std::string name, library;
  int stage = 1;
  std::string description;
};

std::vector<Hostile> hostiles() {
  std::vector<Hostile> list;
  std::ifstream in(PATHWAY_HOSTILE_LIST);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream parts(line);
    for (std::string field; std::getline(parts, field, '|');) fields.push_back(field);
    if (fields.size() == 4) list.push_back({fields[0], fields[1], std::stoi(fields[2]), fields[3]});
  }
  return list;
}

void PrintTo(const Hostile& hostile, std::ostream* out) {
  *out << hostile.name << " (" << hostile.description << ")";
}

// The System V objects the attacks make, under their keys: how many exist, and removed.
int ipcObjectsLeft(bool remove) {
  int left = 0;
  if (const int id = ::shmget(kSharedKey, 0, 0); id >= 0) {
    ++left;
    if (remove) ::shmctl(id, IPC_RMID, nullptr);
  }
  if (const int id = ::msgget(kQueueKey, 0); id >= 0) {
    ++left;
    if (remove) ::msgctl(id, IPC_RMID, nullptr);
  }
  if (const int id = ::semget(kSemaphoreKey, 0, 0); id >= 0) {
    ++left;
    if (remove) ::semctl(id, 0, IPC_RMID);
  }
  return left;
}

// A process of the user the grader's children run as (`sandboxed`: nobody under root; else this
// test's own user), marked by its file-size limit: the classmate a sabotage looks for. Started
// before the grader, so its number is lower.
class Victim {
 public:
  explicit Victim(bool sandboxed) {
    const SandboxUser user = sandboxUser();
    const std::string as = sandboxed && user.changes
                               ? "setpriv --reuid=" + std::to_string(user.uid) +
                                     " --regid=" + std::to_string(user.gid) + " --clear-groups "
                               : "";
    const test::CommandOutcome started =
        test::runCommand(as + "prlimit --fsize=" + std::to_string(kVictimFileLimit) +
                         " sleep 120 > /dev/null 2>&1 & echo $!");
    pid_ = std::atoi(started.output.c_str());
    for (int i = 0; i < 100 && fileLimit() != kVictimFileLimit; ++i) ::usleep(10000);
  }
  ~Victim() {
    if (pid_ > 0) ::kill(pid_, SIGKILL);
  }
  // Its soft limit on file size, from /proc (readable by all, also where root may not prlimit).
  rlim_t fileLimit() const {
    std::ifstream limits("/proc/" + std::to_string(pid_) + "/limits");
    for (std::string line; std::getline(limits, line);)
      if (line.rfind("Max file size", 0) == 0) {
        std::istringstream fields(line.substr(std::string("Max file size").size()));
        std::string soft;
        fields >> soft;
        return soft == "unlimited" ? RLIM_INFINITY : std::stoull(soft);
      }
    return 0;
  }

 private:
  pid_t pid_ = 0;
};

// What each attack's failing case says (when it is more than the skeleton's unfinished TODOs),
// what it must not say (what it would have taken), and how a run without the sandbox shows the
// attack's effect (none: nothing to compare with, or the protection is not the sandbox's).
enum class Control {
  None,
  TookWroteOrCalled,  // loot copied, a file written, a connection made, processes started
  SaysLeak,           // the case's output says what `leak` names
  LeftIpc,            // System V objects left behind
  Sabotaged,          // the victim's file-size limit set to 0
  Passed,             // the attack went through: the case's render was used
};
struct Expectation {
  std::string message;
  std::string leak;  // never in the sandboxed run's results; in the control's for SaysLeak
  Control control = Control::None;
};
const std::map<std::string, Expectation> kExpected = {
    {"read_reference", {"", "", Control::TookWroteOrCalled}},
    {"read_submission", {"", "", Control::TookWroteOrCalled}},
    {"write_outside", {"", "", Control::TookWroteOrCalled}},
    {"setsid_daemon", {"was stopped by the grader's sandbox", "", Control::TookWroteOrCalled}},
    {"fork_bomb", {"was stopped by the grader's sandbox", "", Control::TookWroteOrCalled}},
    {"allocate_100gb", {"std::bad_alloc", "", Control::None}},
    {"huge_file", {"signal 25", "", Control::None}},
    {"network", {"was stopped by the grader's sandbox", "", Control::TookWroteOrCalled}},
    {"framework_function", {"pathway::readExrRaster", "", Control::None}},
    {"copy_reference_splat", {"which is not part of the stage API", "", Control::None}},
    // The reference is absent from the child (its control is ForgedKit.*, below).
    {"forged_kit_stage1", {"the reference stage 1 is not available", "", Control::None}},
    {"forged_kit_stage2", {"the reference stage 2 is not available", "", Control::None}},
    {"forged_kit_stage3", {"as the reference", "", Control::None}},
    {"forged_kit_stage4", {"as the reference", "", Control::None}},
    {"forged_kit_stage5", {"as the reference", "", Control::None}},
    {"late_registration", {"tried to register after its library was loaded", "", Control::None}},
    {"sysv_shared_memory", {"was stopped by the grader's sandbox", "", Control::LeftIpc}},
    {"sysv_copy", {"was stopped by the grader's sandbox", "", Control::None}},
    {"message_queue", {"was stopped by the grader's sandbox", "", Control::LeftIpc}},
    {"prlimit_neighbour", {"limited 0", "", Control::Sabotaged}},
    {"signal_owner",
     {"F_SETOWN refused, PRIO_USER refused", "F_SETOWN accepted", Control::SaysLeak}},
    {"environment", {"=(none)", kToken, Control::SaysLeak}},
    {"inherited_files", {"inherited_files: done", "alice's stage 1", Control::SaysLeak}},
    {"root_powers", {"priority refused, limit refused, hostname refused", "", Control::None}},
    {"fill_disk", {"of files (the grader's limit on what one run may write)", "", Control::Passed}},
    {"exploding_image", {"declares 16384x8192 pixels", "", Control::None}},
};

// A TCP port on this machine the network attack calls: it counts the connections it was offered.
class Listener {
 public:
  Listener() {
    socket_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    if (::bind(socket_, reinterpret_cast<sockaddr*>(&address), size) == 0 &&
        ::listen(socket_, 16) == 0 &&
        ::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &size) == 0)
      port_ = ntohs(address.sin_port);
  }
  ~Listener() { ::close(socket_); }
  int port() const { return port_; }
  int connections() const {
    int count = 0;
    for (int accepted; (accepted = ::accept(socket_, nullptr, nullptr)) >= 0; ++count)
      ::close(accepted);
    return count;
  }

 private:
  int socket_ = -1, port_ = 0;
};

// Processes named by the daemon and the fork bomb that are still alive.
int hostileProcessesAlive() {
  int alive = 0;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream comm(entry.path() / "comm");
    std::string name, state;
    if (!std::getline(comm, name) || name != "pathway-hostile") continue;
    std::ifstream status(entry.path() / "status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("State:", 0) == 0) state = line;
    alive += state.find("Z") == std::string::npos;  // a zombie is gone but for its exit code
  }
  return alive;
}

class HostileStage : public ::testing::TestWithParam<Hostile> {
 protected:
  void SetUp() override {
    if (probeSandbox({}, SandboxMode::Auto).missing.size() > 0)
      GTEST_SKIP() << "this kernel cannot shut student code in completely";
    dir_ = kWork;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ipcObjectsLeft(true);
    // Open to everyone (also to `nobody`, as whom a root grader's children run): only the
    // sandbox keeps an attack out of them.
    fs::permissions(dir_, fs::perms::all);
    drop_ = dir_ / "drop";
    fs::create_directories(drop_);
    fs::permissions(drop_, fs::perms::all);
    fs::create_directories(dir_ / "alice");
    fs::permissions(dir_ / "alice", fs::perms::all);
    secret_ = dir_ / "alice/stage1_filtering.cpp";
    std::ofstream(secret_) << kSecret;
    fs::permissions(secret_, fs::perms::all);
  }
  void TearDown() override {
    ipcObjectsLeft(true);
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // `pathway grade --stage N` of the library, with a secret in the grader's environment, on its
  // standard input and on a descriptor it leaves open (7).
  test::CommandOutcome grade(const Hostile& hostile, const Listener& listener,
                             const std::string& sandbox) {
    std::ofstream(dir_ / "port") << listener.port();
    fs::permissions(dir_ / "port", fs::perms::all);
    return test::runCommand(std::string(kSecretVariable) + "=" + kToken + " " + PATHWAY_BINARY +
                            " grade -q --stage " + std::to_string(hostile.stage) +
                            " --time-limit 30 --sandbox " + sandbox + " --stages-library " +
                            hostile.library + " --report " +
                            (dir_ / ("report-" + sandbox)).string() + " < " + secret_.string() +
                            " 7< " + secret_.string());
  }
  std::string results(const std::string& sandbox) {
    return test::readTextFile((dir_ / ("report-" + sandbox) / "results.json").string());
  }

  static constexpr const char* kSecret = "alice's stage 1\n";
  fs::path dir_, drop_, secret_;
};

TEST_P(HostileStage, FailsAndChangesNothingOutside) {
  const Hostile& hostile = GetParam();
  const Expectation& expected = kExpected.at(hostile.name);
#ifdef PATHWAY_SANITIZED
  // An AddressSanitizer build cannot limit address space (core/sandbox.cpp): 100 GB would be real.
  if (hostile.name == "allocate_100gb") GTEST_SKIP() << "no memory limit in a sanitizer build";
#endif
  const Listener listener;
  ASSERT_GT(listener.port(), 0);
  const Victim victim(true);
  ASSERT_EQ(victim.fileLimit(), kVictimFileLimit);

  const test::CommandOutcome graded = grade(hostile, listener, "auto");
  EXPECT_EQ(graded.exitCode, 1) << graded.output;
  const std::string json = results("auto");
  const std::vector<test::CaseLine> lines = test::caseLines(json);
  ASSERT_EQ(lines.size(), gradingCasesOf(hostile.stage).size()) << graded.output;
  size_t failed = 0, named = 0;
  for (const test::CaseLine& line : lines) {
    failed += line.status == "failed";
    named += line.output.find(expected.message) != std::string::npos;
  }
  EXPECT_EQ(failed, lines.size()) << json;
  EXPECT_GE(named, 1u) << "no case says '" << expected.message << "'\n" << json;
  // Nothing taken, nothing written, nobody called, nobody left, nothing shared, nobody harmed.
  EXPECT_TRUE(fs::is_empty(drop_)) << fs::directory_iterator(drop_)->path();
  EXPECT_EQ(test::readTextFile(secret_.string()), kSecret);
  EXPECT_EQ(listener.connections(), 0);
  EXPECT_EQ(hostileProcessesAlive(), 0);
  EXPECT_EQ(ipcObjectsLeft(true), 0);
  EXPECT_EQ(victim.fileLimit(), kVictimFileLimit);
  EXPECT_EQ(json.find(kToken), std::string::npos) << json;
  EXPECT_EQ(json.find("alice's stage 1"), std::string::npos) << json;
  if (!expected.leak.empty()) {
    EXPECT_EQ(json.find(expected.leak), std::string::npos) << json;
  }
  if (hostile.name == "root_powers") {
    // The user the stage saw from inside is the one the report names, and not root.
    const size_t at = json.find("root_powers: uid=");
    ASSERT_NE(at, std::string::npos) << json;
    const int uid = std::atoi(json.c_str() + at + std::string("root_powers: uid=").size());
    EXPECT_NE(uid, 0) << json;
    EXPECT_NE(json.find("user: uid " + std::to_string(uid) + " (not root)"), std::string::npos)
        << json;
  }

  if (expected.control == Control::None) return;
  // The same attack unconfined does what it set out to do (the grader still ends what it starts).
  const Victim unconfinedVictim(false);  // of the user an unconfined child runs as
  const test::CommandOutcome control = grade(hostile, listener, "off");
  const std::string outputs = results("off");
  switch (expected.control) {
    case Control::TookWroteOrCalled:
      EXPECT_TRUE(!fs::is_empty(drop_) || test::readTextFile(secret_.string()) != kSecret ||
                  listener.connections() > 0 ||
                  outputs.find("outlived its render") != std::string::npos)
          << "the attack did nothing even without the sandbox: it tests nothing\n"
          << control.output;
      break;
    case Control::SaysLeak:
      EXPECT_NE(outputs.find(expected.leak), std::string::npos) << outputs;
      break;
    case Control::LeftIpc:
      EXPECT_GT(ipcObjectsLeft(true), 0) << outputs;
      break;
    case Control::Sabotaged:
      EXPECT_EQ(unconfinedVictim.fileLimit(), 0u) << outputs;
      break;
    case Control::Passed:
      EXPECT_EQ(outputs.find(expected.message), std::string::npos) << outputs;
      break;
    case Control::None:
      break;
  }
  EXPECT_EQ(hostileProcessesAlive(), 0) << "the grader ends what a stage starts, sandbox or not";
}

INSTANTIATE_TEST_SUITE_P(Hostile, HostileStage, ::testing::ValuesIn(hostiles()),
                         [](const ::testing::TestParamInfo<Hostile>& info) {
                           return info.param.name;
                         });

// The forged kits' control: in a process that holds the reference (this test program, the
// reference built in), and with the gate open as it is while a program starts, the attacks go
// through: the student's stage 1 or 2 becomes the reference's, or the reference's stage is
// registered again. (In a child process: they change this program's registry.)
TEST(ForgedKit, GoesThroughWhereTheReferenceIsPresentAndTheGateOpen) {
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages built in";
  for (const Hostile& hostile : hostiles()) {
    if (hostile.name.rfind("forged_kit_stage", 0) != 0) continue;
    EXPECT_EXIT(
        {
          const size_t before = registrationLog().size();
          if (!dlopen(hostile.library.c_str(), RTLD_NOW | RTLD_LOCAL)) std::exit(3);
          const StageKit student(5, Variant::Student, EarlierStages::Own);
          const StageKit reference(5, Variant::Reference, EarlierStages::Own);
          bool through = false;
          if (hostile.stage == 1) through = student.stage1().splat == reference.stage1().splat;
          if (hostile.stage == 2)
            through = student.stage2().ambientOcclusionSample ==
                      reference.stage2().ambientOcclusionSample;
          const std::vector<std::string>& log = registrationLog();
          for (size_t i = before; i < log.size(); ++i)
            through = through || log[i].find('@') != std::string::npos;
          std::exit(through ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "")
        << hostile.name;
  }
}

// Two students in one class run: one leaves its library in System V shared memory, the other
// looks for it there. With the sandbox neither gets anywhere and nothing is left; unconfined, one
// after the other, the second finds and loads the first's library.
TEST(HostileClass, TwoStudentsInOneRunCannotReachEachOther) {
  if (probeSandbox({}, SandboxMode::Auto).missing.size() > 0)
    GTEST_SKIP() << "this kernel cannot shut student code in completely";
  const fs::path dir = test::freshTestFolder("pathway_hostile_class");
  ipcObjectsLeft(true);
  const auto submission = [&](const std::string& student, const std::string& attack) {
    const fs::path folder = dir / "class" / student;
    fs::create_directories(folder);
    std::ofstream(folder / "stage1_filtering.cpp")
        << "#define PATHWAY_HOSTILE_WORK \"" << kWork.string() << "\"\n"
        << "#define PATHWAY_HOSTILE_REFERENCES \"" << PATHWAY_SCENES_DIR << "/references\"\n"
        << test::readTextFile(PATHWAY_SOURCE_DIR "/assignments/stage1/stage1_filtering.cpp")
        << test::readTextFile(std::string(PATHWAY_SOURCE_DIR) + "/tests/hostile/" + attack +
                              ".cpp");
    fs::copy_file(PATHWAY_SOURCE_DIR "/tests/hostile/hostile_kit.h", folder / "hostile_kit.h");
    return folder.string();
  };
  const std::string alice = submission("alice", "sysv_shared_memory");
  const std::string bob = submission("bob", "sysv_copy");
  const std::string grade = std::string(PATHWAY_BINARY) + " grade -q --stage 1 --time-limit 30";
  const test::CommandOutcome together = test::runCommand(
      grade + " --submissions " + (dir / "class").string() + " --output " + (dir / "out").string());
  const std::string bobs = test::readTextFile((dir / "out/bob/results.json").string());
  EXPECT_NE(bobs.find("was stopped by the grader's sandbox"), std::string::npos)
      << together.output << bobs;
  EXPECT_EQ(bobs.find("loaded a classmate's library"), std::string::npos) << bobs;
  EXPECT_EQ(ipcObjectsLeft(true), 0);

  // Unconfined, alice first, then bob: he finds her library and loads it.
  test::runCommand(grade + " --sandbox off --submission " + alice + " --output " +
                   (dir / "alice-off").string());
  EXPECT_GT(ipcObjectsLeft(false), 0) << "alice left nothing: the control tests nothing";
  test::runCommand(grade + " --sandbox off --submission " + bob + " --output " +
                   (dir / "bob-off").string());
  const std::string unconfined = test::readTextFile((dir / "bob-off/results.json").string());
  EXPECT_NE(unconfined.find("loaded a classmate's library of"), std::string::npos) << unconfined;
  ipcObjectsLeft(true);
  fs::remove_all(dir);
}

// The shipped stage-1 references, baked into a stage file as arrays: its splat puts each
// pixel's reference value in that pixel (the reference picked by the film's filter radius).
std::string bakedReferencesStage() {
  std::ostringstream source;
  source << test::readTextFile(PATHWAY_SOURCE_DIR "/assignments/stage1/stage1_filtering.cpp")
         << "\nnamespace pathway {\nnamespace {\nstruct Baked { float radius; int width; "
            "const float* rgb; };\n";
  std::vector<std::pair<float, std::string>> baked;
  for (const GradingCase* c : gradingCasesOf(1)) {
    if (c->courseOnly) continue;  // the handout does not have these
    const GradingReference reference =
        readGradingReference(std::string(PATHWAY_SCENES_DIR) + "/references/" + c->referenceFile());
    const std::string array = "baked_" + std::to_string(baked.size());
    source << "const float " << array << "[] = {";
    source.precision(9);
    for (size_t i = 0; i < reference.mean.pixels.size(); ++i) {
      const Color& pixel = reference.mean.pixels[i];
      source << pixel.x << "," << pixel.y << "," << pixel.z << (i % 4 == 3 ? ",\n" : ",");
    }
    source << "};\n";
    const float radius = c->filterRadius > 0 ? c->filterRadius : naturalFilterRadius(c->filter);
    baked.push_back({radius, "{" + std::to_string(radius) + "f, " +
                                 std::to_string(reference.mean.width) + ", " + array + "}"});
  }
  source << "const Baked kBaked[] = {";
  for (const auto& [radius, entry] : baked) source << entry << ",";
  source << "};\n"
            "void bakedSplat(FilmBlock& film, Vec2 p, const Color& radiance, "
            "const PixelFilter& filter) {\n"
            "  const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);\n"
            "  for (const Baked& b : kBaked)\n"
            "    if (b.radius == filter.radius()) {\n"
            "      const float* v = b.rgb + 3 * (static_cast<size_t>(y) * b.width + x);\n"
            "      return film.addSample(x, y, 1.0f, Color(v[0], v[1], v[2]));\n"
            "    }\n"
            "  film.addSample(x, y, 1.0f, radiance);\n"
            "}\n"
            "const bool baking = registerStage<EyeLightIntegrator>(stage1(), Stage1Functions{"
            "{boxFilter, tentFilter, mitchellNetravaliFilter, gaussianFilter}, bakedSplat});\n"
            "}  // namespace\n}  // namespace pathway\n";
  return source.str();
}

TEST(HostileBaked, ReferencesBakedIntoTheSourceFailAsTooCloseAndOnTheCourseCases) {
  if (!test::kFullRepository) GTEST_SKIP() << "needs the course's own cases";
  const fs::path dir = test::freshTestFolder("pathway_hostile_baked");
  fs::permissions(dir, fs::perms::all);
  fs::create_directories(dir / "submission");
  fs::permissions(dir / "submission", fs::perms::all);
  std::ofstream(dir / "submission/stage1_filtering.cpp") << bakedReferencesStage();
  const test::CommandOutcome graded =
      test::runCommand(std::string(PATHWAY_BINARY) + " grade -q --stage 1 --submission " +
                       (dir / "submission").string() + " --output " + (dir / "out").string());
  EXPECT_EQ(graded.exitCode, 1) << graded.output;
  const std::vector<test::CaseLine> lines =
      test::caseLines(test::readTextFile((dir / "out/results.json").string()));
  ASSERT_EQ(lines.size(), gradingCasesOf(1).size()) << graded.output;
  // Every shipped case fails. The first case of each filter radius gets its own reference back and
  // is too close to be true; a later case with the same radius gets the first one's image (of
  // another scene or size). The course's own cases fail: the handout has no image of them.
  std::set<float> radii;
  size_t tooClose = 0, shippedFailed = 0, shipped = 0, courseFailed = 0;
  for (const GradingCase* c : gradingCasesOf(1)) {
    const std::string name = "Stage 1 · " + c->name;
    for (const test::CaseLine& line : lines) {
      if (line.name != name) continue;
      if (c->courseOnly) {
        courseFailed += line.status == "failed";
        continue;
      }
      ++shipped;
      shippedFailed += line.status == "failed";
      radii.insert(c->filterRadius > 0 ? c->filterRadius : naturalFilterRadius(c->filter));
      tooClose += line.output.find("too close to be true") != std::string::npos;
    }
  }
  const std::string results = test::readTextFile((dir / "out/results.json").string());
  EXPECT_EQ(shippedFailed, shipped) << results;
  EXPECT_GE(tooClose, radii.size()) << results;
  EXPECT_GE(courseFailed, 1u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pathway
