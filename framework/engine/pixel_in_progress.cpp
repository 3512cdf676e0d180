#include "engine/pixel_in_progress.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstring>

namespace pathway {
namespace {

// One slot per rendering thread; more threads than slots simply go unrecorded.
constexpr int kSlots = 256;
constexpr int64_t kNoPixel = -1;
std::atomic<int64_t> slots[kSlots];  // x << 32 | y, or kNoPixel
std::atomic<int> slotsTaken{0};
constexpr const char* kMarker = "while rendering pixel ";

int64_t pack(int x, int y) {
  return (int64_t(x) << 32) | uint32_t(y);
}

std::atomic<int64_t>* mySlot() {
  thread_local const int index = slotsTaken.fetch_add(1, std::memory_order_relaxed);
  return index < kSlots ? &slots[index] : nullptr;
}

// Async-signal-safe output: write(2) and hand-made number formatting only.
void put(const char* text) {
  (void)!::write(STDERR_FILENO, text, std::strlen(text));
}
void putNumber(int64_t value) {
  char digits[24];
  int n = 0;
  const bool negative = value < 0;
  uint64_t v = negative ? uint64_t(-value) : uint64_t(value);
  do digits[n++] = char('0' + v % 10);
  while ((v /= 10) != 0 && n < 23);
  if (negative) put("-");
  char out[24];
  for (int i = 0; i < n; ++i) out[i] = digits[n - 1 - i];
  out[n] = '\0';
  put(out);
}

std::atomic<bool> reporting{false};

void onFatalSignal(int signal) {
  // Render threads running the same faulty code often fault together: the first one reports and
  // ends the process; the others wait for that, so the report's lines are never interleaved.
  if (reporting.exchange(true)) {
    for (;;) ::pause();
  }
  put("\npathway: stopped by SIG");
  put(sigabbrev_np(signal) ? sigabbrev_np(signal) : "NAL");
  bool first = true;
  const int taken = slotsTaken.load(std::memory_order_relaxed);
  for (int i = 0; i < taken && i < kSlots; ++i) {
    const int64_t packed = slots[i].load(std::memory_order_relaxed);
    if (packed == kNoPixel) continue;
    put(first ? " " : ", ");
    if (first) put(kMarker);
    first = false;
    put("(");
    putNumber(packed >> 32);
    put(", ");
    putNumber(int32_t(uint32_t(packed)));
    put(")");
  }
  put("\n");
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void recordPixelInProgress(int x, int y) {
  if (std::atomic<int64_t>* slot = mySlot()) slot->store(pack(x, y), std::memory_order_relaxed);
}

void clearPixelInProgress() {
  if (std::atomic<int64_t>* slot = mySlot()) slot->store(kNoPixel, std::memory_order_relaxed);
}

void reportPixelsOnFatalSignals() {
  for (std::atomic<int64_t>& slot : slots) slot.store(kNoPixel);
  for (int signal : {SIGSEGV, SIGILL, SIGFPE, SIGBUS, SIGABRT, SIGALRM})
    std::signal(signal, onFatalSignal);
}

std::string pixelsInProgressFrom(const std::string& output) {
  const size_t at = output.find(kMarker);
  if (at == std::string::npos) return "";
  const size_t start = at + std::strlen(kMarker);
  return output.substr(start, output.find('\n', start) - start);
}

}  // namespace pathway
