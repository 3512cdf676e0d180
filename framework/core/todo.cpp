#include "core/todo.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>

namespace pathway {
namespace {

std::mutex todoMutex;
std::vector<const TodoSite*> sitesPrinted;  // guarded by todoMutex
std::vector<const TodoSite*> sitesHit;      // guarded by todoMutex
std::atomic<unsigned> generation{1};

std::string relativeToProject(const char* file) {
#ifdef PATHWAY_SOURCE_DIR
  const char* root = PATHWAY_SOURCE_DIR "/";
  if (std::strncmp(file, root, std::strlen(root)) == 0) return file + std::strlen(root);
#endif
  return file;
}

}  // namespace

unsigned todoGeneration() {
  return generation.load(std::memory_order_relaxed);
}

void reportTodo(TodoSite& site) {
  std::lock_guard<std::mutex> lock(todoMutex);
  site.generationSeen.store(generation.load());
  if (std::find(sitesHit.begin(), sitesHit.end(), &site) == sitesHit.end())
    sitesHit.push_back(&site);
  if (std::find(sitesPrinted.begin(), sitesPrinted.end(), &site) != sitesPrinted.end()) return;
  sitesPrinted.push_back(&site);
  std::fprintf(stderr, "TODO not done yet: %s:%d: %s (a placeholder runs meanwhile)\n",
               relativeToProject(site.file).c_str(), site.line, site.task);
}

std::vector<TodoRecord> todosHit() {
  std::lock_guard<std::mutex> lock(todoMutex);
  std::vector<TodoRecord> result;
  for (const TodoSite* site : sitesHit)
    result.push_back({relativeToProject(site->file), site->line, site->task});
  return result;
}

void clearTodosHit() {
  std::lock_guard<std::mutex> lock(todoMutex);
  sitesHit.clear();
  generation.fetch_add(1);
}

}  // namespace pathway
