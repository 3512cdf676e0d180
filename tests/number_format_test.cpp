// The small text helpers that keys, file names and reports are built from (core/number_format.h,
// core/stable_hash.h), against values worked out by hand or published with the algorithm.
#include "core/number_format.h"

#include <gtest/gtest.h>

#include "core/stable_hash.h"

namespace pathway {
namespace {

TEST(NumberFormat, WritesTheNumberAsThePatternSays) {
  EXPECT_EQ("1.23e+03", formatNumber("%.3g", 1234.5));
  EXPECT_EQ("0.50 s", formatNumber("%.2f s", 0.5));
  EXPECT_EQ("-12.5%", formatNumber("%+.1f%%", -12.5));
}

TEST(NumberFormat, HexDigitsAreZeroPaddedToTheWidthAsked) {
  EXPECT_EQ("0000000000000abc", hexDigits(0xabc));
  EXPECT_EQ("00000abc", hexDigits(0xabc, 8));  // a CRC-32 in a reference library's seal
  EXPECT_EQ("ffffffff", hexDigits(0xffffffffu, 8));
  EXPECT_EQ("ffffffffffffffff", hexDigits(~uint64_t{0}));
}

// FNV-1a's 64-bit offset basis is the hash of no bytes; "a" is the first test vector of its
// authors' reference code (offset basis XOR 0x61, times the FNV prime 0x100000001b3).
TEST(NumberFormat, StableHashIsFnv1a) {
  EXPECT_EQ("cbf29ce484222325", hexDigits(stableHash("")));
  EXPECT_EQ("af63dc4c8601ec8c", hexDigits(stableHash("a")));
}

}  // namespace
}  // namespace pathway
