// One number as printf's `pattern` writes it ("%.3g", "%.2f s", "%+.1f%%"): the helper the panel,
// the reports, the charts and the likely causes format their numbers with; and a hash or
// checksum as hexadecimal digits.
#pragma once

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>

namespace pathway {

inline std::string formatNumber(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// A value in hexadecimal, zero-padded to `digits` (up to 16, all a 64-bit value can need): a hash
// (16) or a CRC-32 (8) as a key or a file name.
inline std::string hexDigits(uint64_t value, int digits = 16) {
  char text[17];
  std::snprintf(text, sizeof text, "%0*" PRIx64, digits < 16 ? digits : 16, value);
  return text;
}

// A size in bytes in binary units: "4 GiB" where it is whole gibibytes, else mebibytes ("64 MiB").
inline std::string bytesText(uint64_t bytes) {
  if (bytes >= (1ull << 30) && bytes % (1ull << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  return std::to_string(bytes >> 20) + " MiB";
}

}  // namespace pathway
