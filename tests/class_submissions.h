// The test class of six stage-2 submissions every class-grading test grades: alice (correct),
// bob (a planted bug: the cosine dropped), carol (does not compile), dave (crashes), erin (hangs
// past a short time limit), frank (the stage file is missing).
#pragma once

#include <filesystem>
#include <string>

namespace pathway::test {

// Makes the six submission folders in `submissions` from the solutions; false if one failed.
bool makeTestClass(const std::filesystem::path& submissions);

// The class.csv row of `name` in `table` ("" when absent).
std::string classRow(const std::string& table, const std::string& name);

// Checks each verdict of the six in the class table `output`/class.csv and their files.
void expectTestClassVerdicts(const std::filesystem::path& output);

}  // namespace pathway::test
