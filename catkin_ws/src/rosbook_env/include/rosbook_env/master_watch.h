// MasterWatch: keeps a roscpp node in the graph when roscore is killed and started again.
//
// ROS 1 nodes outlive their master, but roscpp registers its publishers, subscribers and
// services only once: a new master knows none of them. Construct one MasterWatch in main()
// after the node has advertised and subscribed; a thread of its own asks the master for
// its pid and /run_id once a wall second and, when they change (a new master; the same
// one answering late, or getting its /run_id after it first answered, changes nothing: see
// same_master), registers everything again (see master_watch.cpp).
#ifndef ROSBOOK_ENV_MASTER_WATCH_H
#define ROSBOOK_ENV_MASTER_WATCH_H

#include <memory>
#include <string>
#include <thread>

namespace rosbook_env {

// Who a master is: its pid and /run_id ("" while it has none).
struct MasterIdentity {
  int pid = 0;
  std::string run_id;
  bool operator==(const MasterIdentity& other) const { return pid == other.pid && run_id == other.run_id; }
};

// Whether the master answering now (`seen`) is `known`, the one the node registered with.
// roscore's roslaunch sets /run_id after its rosmaster answers (it checks for the master
// every 0.1 s, then sets it), so a watch that registered in between knows that master's
// pid with no run_id yet: the run_id arriving later is the same master, not a second
// restart. (A new master with the very same pid is told apart by its run_id.)
bool same_master(const MasterIdentity& known, const MasterIdentity& seen);

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
