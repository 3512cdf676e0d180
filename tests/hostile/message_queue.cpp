// Leaves IPC behind that outlives the case: a System V message queue with a message in it and a
// semaphore set, under fixed keys (a later grading of anyone could read them).
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>

#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  const int queue = msgget(hostile::kQueueKey, IPC_CREAT | 0666);
  if (queue >= 0) {
    struct {
      long type = 1;
      char text[16] = "stage 1 answers";
    } message;
    msgsnd(queue, &message, sizeof message.text, IPC_NOWAIT);
  }
  semget(hostile::kSemaphoreKey, 1, IPC_CREAT | 0666);
  return true;
}();
}  // namespace
