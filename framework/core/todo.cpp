#include "core/todo.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace pathway {
namespace {

std::atomic<uint64_t> nextLogId{1};
thread_local TodoLog* currentLog = nullptr;

std::string relativeToProject(const char* file) {
#ifdef PATHWAY_SOURCE_DIR
  const char* root = PATHWAY_SOURCE_DIR "/";
  if (std::strncmp(file, root, std::strlen(root)) == 0) return file + std::strlen(root);
#endif
  return file;
}

}  // namespace

TodoLog::TodoLog() : id_(nextLogId.fetch_add(1)) {}

void TodoLog::record(const TodoSite& site) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (std::find(sites_.begin(), sites_.end(), &site) == sites_.end()) sites_.push_back(&site);
}

std::vector<TodoRecord> TodoLog::records() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<TodoRecord> result;
  for (const TodoSite* site : sites_)
    result.push_back({relativeToProject(site->file), site->line, site->task});
  return result;
}

CurrentTodoLog::CurrentTodoLog(TodoLog* log) : previous_(currentLog) {
  currentLog = log;
}

CurrentTodoLog::~CurrentTodoLog() {
  currentLog = previous_;
}

uint64_t currentTodoLogId() {
  return currentLog ? currentLog->id() : 0;
}

void reportTodo(TodoSite& site) {
  TodoLog* log = currentLog;
  if (log) log->record(site);
  site.logSeen.store(log ? log->id() : 0, std::memory_order_relaxed);
  if (site.printed.exchange(true)) return;
  std::fprintf(stderr, "TODO not done yet: %s:%d: %s (a placeholder runs meanwhile)\n",
               relativeToProject(site.file).c_str(), site.line, site.task);
}

}  // namespace pathway
