// Copying between students, the giving half: puts its own stage library into a System V
// shared-memory segment (a fixed key), which outlives the process unless someone removes it.
#include <dlfcn.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstring>

#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  Dl_info self{};
  if (!dladdr(reinterpret_cast<void*>(&hostile::work), &self) || !self.dli_fname) return false;
  const std::string library = hostile::readFile(self.dli_fname);
  const int segment = shmget(hostile::kSharedKey, library.size() + 8, IPC_CREAT | 0666);
  if (segment < 0) return false;
  void* memory = shmat(segment, nullptr, 0);
  if (memory == reinterpret_cast<void*>(-1)) return false;
  const uint64_t size = library.size();
  std::memcpy(memory, &size, 8);
  std::memcpy(static_cast<char*>(memory) + 8, library.data(), library.size());
  shmdt(memory);
  return true;
}();
}  // namespace
