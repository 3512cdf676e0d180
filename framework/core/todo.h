// PATHWAY_TODO("what to write") marks an unfinished piece of a stage. The first time it runs it
// prints, once, the file and line to open; it never stops the program, so a skeleton still renders
// its placeholder. The list of TODOs that ran tells the CLI and the grader that a stage is
// unfinished.
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace pathway {

struct TodoSite {
  const char* file;
  int line;
  const char* task;
  std::atomic<unsigned> generationSeen{0};  // lets the hot path skip the lock after the first hit
};

struct TodoRecord {
  std::string file;  // relative to the project root
  int line;
  std::string task;
};

unsigned todoGeneration();
// Records that a TODO ran; prints it the first time a given site runs in this process.
void reportTodo(TodoSite& site);

// Every distinct TODO that has run since the last clearTodosHit(), in the order first seen.
std::vector<TodoRecord> todosHit();

// Forgets the TODOs hit so far (tests and the grader use it to check one stage at a time).
void clearTodosHit();

}  // namespace pathway

#define PATHWAY_TODO(task)                                                \
  do {                                                                    \
    static ::pathway::TodoSite pathwayTodoSite{__FILE__, __LINE__, task}; \
    if (pathwayTodoSite.generationSeen.load(std::memory_order_relaxed) != \
        ::pathway::todoGeneration())                                      \
      ::pathway::reportTodo(pathwayTodoSite);                             \
  } while (false)
