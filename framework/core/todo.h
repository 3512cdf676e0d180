// PATHWAY_TODO("what to write") marks an unfinished piece of a stage. The first time it runs it
// prints, once per process, the file and line to open; it never stops the program, so a skeleton
// still renders its placeholder. Each render keeps its own log of the TODOs that ran (TodoLog),
// which tells the CLI, the viewer and the grader that a stage is unfinished.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace pathway {

struct TodoSite {
  const char* file;
  int line;
  const char* task;
  // The log this site last went into: lets the hot path skip the locks after the first hit.
  std::atomic<uint64_t> logSeen{UINT64_MAX};
  std::atomic<bool> printed{false};  // its line went to stderr (once per process)
};

struct TodoRecord {
  std::string file;  // relative to the project root
  int line;
  std::string task;
};

// The TODOs one render ran, in the order first seen. A Renderer owns one and makes it the
// current log of each thread while that thread renders one of its tiles, so renders that run
// side by side (the viewer's panes and its reference) keep apart what each of them ran.
class TodoLog {
 public:
  TodoLog();
  TodoLog(const TodoLog&) = delete;
  TodoLog& operator=(const TodoLog&) = delete;

  uint64_t id() const { return id_; }
  void record(const TodoSite& site);
  std::vector<TodoRecord> records() const;

 private:
  const uint64_t id_;
  mutable std::mutex mutex_;
  std::vector<const TodoSite*> sites_;
};

// While it lives, the TODOs that run on this thread go into `log` (nullptr: into none).
class CurrentTodoLog {
 public:
  explicit CurrentTodoLog(TodoLog* log);
  ~CurrentTodoLog();
  CurrentTodoLog(const CurrentTodoLog&) = delete;
  CurrentTodoLog& operator=(const CurrentTodoLog&) = delete;

 private:
  TodoLog* previous_;
};

// The id of this thread's current log; 0 when there is none.
uint64_t currentTodoLogId();
// Records that a TODO ran in the current log; prints it the first time a site runs in this
// process.
void reportTodo(TodoSite& site);

}  // namespace pathway

#define PATHWAY_TODO(task)                                                                        \
  do {                                                                                            \
    static ::pathway::TodoSite pathwayTodoSite{__FILE__, __LINE__, task};                         \
    if (pathwayTodoSite.logSeen.load(std::memory_order_relaxed) != ::pathway::currentTodoLogId()) \
      ::pathway::reportTodo(pathwayTodoSite);                                                     \
  } while (false)
