#include "batch_scheduling.hpp"

#include <dirent.h>
#include <sched.h>

#include <cstdlib>

namespace bullet_turtlebot {

bool use_batch_scheduling() {
  DIR* tasks = opendir("/proc/self/task");
  if (!tasks) return false;
  bool all = true;
  sched_param param{};
  param.sched_priority = 0;
  while (const dirent* entry = readdir(tasks)) {
    const int tid = std::atoi(entry->d_name);
    if (tid <= 0) continue;
    all = sched_setscheduler(tid, SCHED_BATCH, &param) == 0 && all;
  }
  closedir(tasks);
  return all;
}

}  // namespace bullet_turtlebot
