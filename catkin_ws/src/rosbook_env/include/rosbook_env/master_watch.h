// MasterWatch: keeps a roscpp node in the graph when roscore is killed and started again.
//
// ROS 1 nodes outlive their master, but roscpp registers its publishers, subscribers and
// services only once: a new master knows none of them. Construct one MasterWatch in main()
// after the node has advertised and subscribed; a thread of its own asks the master for
// its pid and /run_id once a wall second and, when they change (a new master; the same
// one answering late changes nothing), registers everything again (see master_watch.cpp).
#ifndef ROSBOOK_ENV_MASTER_WATCH_H
#define ROSBOOK_ENV_MASTER_WATCH_H

#include <memory>
#include <string>
#include <thread>

namespace rosbook_env {

class MasterWatch {
 public:
  // poll: wall seconds between checks of the master.
  explicit MasterWatch(double poll = 1.0);
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;

  // A service advertised after the watch started (resolved name); those advertised before
  // are found on the master when the watch starts.
  void watch_service(const std::string& name);

 private:
  // Everything the thread uses, kept alive by the thread if the destructor has to let it go.
  struct State;
  static void run(std::shared_ptr<State> state);

  std::shared_ptr<State> state_;
  std::thread thread_;
};

}  // namespace rosbook_env

#endif  // ROSBOOK_ENV_MASTER_WATCH_H
