// Prints what the grader's environment holds: a variable with a secret-looking name.
#include <cstdio>
#include <cstdlib>

#include "hostile_kit.h"
extern char** environ;
namespace {
const bool attacked = []() -> bool {
  const char* secret = std::getenv(hostile::kSecretVariable);
  std::printf("environment: %s=%s; %d variables\n", hostile::kSecretVariable,
              secret ? secret : "(none)", [] {
                int count = 0;
                for (char** entry = environ; *entry; ++entry) ++count;
                return count;
              }());
  std::fflush(stdout);
  std::abort();  // so that what it printed is in the report
}();
}  // namespace
