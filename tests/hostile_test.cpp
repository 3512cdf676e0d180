// The hostile-submission suite (tests/hostile/): stage files that attack the grader instead of
// doing the work. Each must end in a failed case or a refused load with a clear message, and
// leave nothing outside the grader's own folders changed and no process behind. Where an attack
// has an effect to see, it is run once more with --sandbox off, as a control: there it works
// (loot copied out, a file written, a connection made, processes started), which shows the
// sandbox is what stops it. A stage with the shipped references baked into its source fails too:
// as too close to the references on the shipped cases, and on the course's own cases.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/sandbox.h"
#include "grade/grading_cases.h"
#include "grade/grading_reference.h"
#include "grade_results.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

struct Hostile {
  std::string name, library, description;
};

std::vector<Hostile> hostiles() {
  std::vector<Hostile> list;
  std::ifstream in(PATHWAY_HOSTILE_LIST);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream parts(line);
    for (std::string field; std::getline(parts, field, '|');) fields.push_back(field);
    if (fields.size() == 3) list.push_back({fields[0], fields[1], fields[2]});
  }
  return list;
}

void PrintTo(const Hostile& hostile, std::ostream* out) {
  *out << hostile.name << " (" << hostile.description << ")";
}

// What each attack's failing case says (when it is more than the skeleton's unfinished TODOs),
// and whether a run without the sandbox shows an effect to compare with.
struct Expectation {
  std::string message;
  bool control = false;
};
const std::map<std::string, Expectation> kExpected = {
    {"read_reference", {"", true}},
    {"read_submission", {"", true}},
    {"write_outside", {"", true}},
    {"setsid_daemon", {"was stopped by the grader's sandbox", true}},
    {"fork_bomb", {"was stopped by the grader's sandbox", true}},
    {"allocate_100gb", {"std::bad_alloc", false}},
    {"huge_file", {"signal 25", false}},
    {"network", {"was stopped by the grader's sandbox", true}},
    {"framework_function", {"pathway::readExrRaster", false}},
    {"copy_reference_splat", {"which is not part of the stage API", false}},
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
    dir_ = test::freshTestFolder("pathway_hostile");
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
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // `pathway grade --stage 1` of the library, with the attack's settings in its environment.
  test::CommandOutcome grade(const Hostile& hostile, const Listener& listener,
                             const std::string& sandbox) {
    const std::string references = std::string(PATHWAY_SCENES_DIR) + "/references";
    return test::runCommand(
        "PATHWAY_HOSTILE_DROP=" + drop_.string() + " PATHWAY_HOSTILE_SECRET=" + secret_.string() +
        " PATHWAY_HOSTILE_REFERENCE=" + references + "/stage1-cornell-box.exr" +
        " PATHWAY_HOSTILE_REFERENCES=" + references +
        " PATHWAY_HOSTILE_PORT=" + std::to_string(listener.port()) + " " + PATHWAY_BINARY +
        " grade -q --stage 1 --time-limit 30 --sandbox " + sandbox + " --stages-library " +
        hostile.library + " --report " + (dir_ / ("report-" + sandbox)).string());
  }
  std::vector<test::CaseLine> results(const std::string& sandbox) {
    return test::caseLines(
        test::readTextFile((dir_ / ("report-" + sandbox) / "results.json").string()));
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

  const test::CommandOutcome graded = grade(hostile, listener, "auto");
  EXPECT_EQ(graded.exitCode, 1) << graded.output;
  const std::vector<test::CaseLine> lines = results("auto");
  ASSERT_EQ(lines.size(), gradingCasesOf(1).size()) << graded.output;
  size_t failed = 0, named = 0;
  for (const test::CaseLine& line : lines) {
    failed += line.status == "failed";
    named += line.output.find(expected.message) != std::string::npos;
  }
  EXPECT_GE(failed, 1u);
  EXPECT_GE(named, 1u) << "no case says '" << expected.message << "'";
  // Nothing taken, nothing written, nobody called, nobody left.
  EXPECT_TRUE(fs::is_empty(drop_)) << fs::directory_iterator(drop_)->path();
  EXPECT_EQ(test::readTextFile(secret_.string()), kSecret);
  EXPECT_EQ(listener.connections(), 0);
  EXPECT_EQ(hostileProcessesAlive(), 0);

  if (!expected.control) return;
  // The same attack unconfined does what it set out to do (the grader still ends what it starts).
  const test::CommandOutcome control = grade(hostile, listener, "off");
  const std::string outputs = test::readTextFile((dir_ / "report-off/results.json").string());
  const bool tookOrWrote = !fs::is_empty(drop_) || test::readTextFile(secret_.string()) != kSecret;
  const bool called = listener.connections() > 0;
  const bool startedProcesses = outputs.find("outlived its render") != std::string::npos;
  EXPECT_TRUE(tookOrWrote || called || startedProcesses)
      << "the attack did nothing even without the sandbox: it tests nothing\n"
      << control.output;
  EXPECT_EQ(hostileProcessesAlive(), 0) << "the grader ends what a stage starts, sandbox or not";
}

INSTANTIATE_TEST_SUITE_P(Hostile, HostileStage, ::testing::ValuesIn(hostiles()),
                         [](const ::testing::TestParamInfo<Hostile>& info) {
                           return info.param.name;
                         });

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
