// Re-registration with a restarted master: what roscpp's TopicManager and ServiceManager do
// once at start-up, done again with the node's existing XML-RPC and TCPROS ports.
#include "rosbook_env/master_watch.h"

#include <ros/connection_manager.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <ros/service_manager.h>
#include <ros/service_publication.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <set>
#include <vector>

namespace rosbook_env {
namespace {

using XmlRpc::XmlRpcValue;

// How long the destructor waits for a watch stuck in a call to a master that stopped
// answering (roscpp's XML-RPC has no timeout); then it lets the thread go.
constexpr std::chrono::seconds kStopWait(3);

XmlRpcValue caller_args() {
  XmlRpcValue args;
  args[0] = ros::this_node::getName();
  return args;
}

bool master_call(const std::string& method, const XmlRpcValue& args, XmlRpcValue* payload) {
  XmlRpcValue response;
  // wait_for_master false: one attempt, no "waiting for master" loop, no error printed.
  return ros::master::execute(method, args, response, *payload, false);
}

// The node's own slave API, over XML-RPC as the master would call it.
bool node_call(const std::string& method, const XmlRpcValue& args, XmlRpcValue* payload) {
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(ros::XMLRPCManager::instance()->getServerURI(), host, port)) return false;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpcValue response;
  if (!client.execute(method.c_str(), args, response) || client.isFault()) return false;
  return ros::XMLRPCManager::instance()->validateXmlrpcResponse(method, response, *payload);
}

// [[topic, type], ...] from getPublications / getSubscriptions.
std::vector<std::pair<std::string, std::string>> topic_list(const std::string& method) {
  std::vector<std::pair<std::string, std::string>> topics;
  XmlRpcValue payload;
  if (!node_call(method, caller_args(), &payload) || payload.getType() != XmlRpcValue::TypeArray) return topics;
  for (int i = 0; i < payload.size(); ++i) {
    XmlRpcValue& entry = payload[i];
    if (entry.getType() == XmlRpcValue::TypeArray && entry.size() >= 2 &&
        entry[0].getType() == XmlRpcValue::TypeString && entry[1].getType() == XmlRpcValue::TypeString)
      topics.emplace_back(static_cast<std::string>(entry[0]), static_cast<std::string>(entry[1]));
  }
  return topics;
}

// Publishers this node's subscription to `topic` is connected to now (from getBusInfo:
// [id, publisher URI, "i", transport, topic, ...] for inbound links).
std::set<std::string> connected_publishers(const std::string& topic) {
  std::set<std::string> uris;
  XmlRpcValue payload;
  if (!node_call("getBusInfo", caller_args(), &payload) || payload.getType() != XmlRpcValue::TypeArray) return uris;
  for (int i = 0; i < payload.size(); ++i) {
    XmlRpcValue& link = payload[i];
    if (link.getType() != XmlRpcValue::TypeArray || link.size() < 5) continue;
    if (link[1].getType() != XmlRpcValue::TypeString || link[2].getType() != XmlRpcValue::TypeString ||
        link[4].getType() != XmlRpcValue::TypeString)
      continue;
    if (static_cast<std::string>(link[2]) == "i" && static_cast<std::string>(link[4]) == topic)
      uris.insert(static_cast<std::string>(link[1]));
  }
  return uris;
}

}  // namespace

bool same_master(const MasterIdentity& known, const MasterIdentity& seen) {
  return seen == known || (seen.pid == known.pid && known.run_id.empty());
}

struct MasterWatch::State {
  explicit State(double period) : poll(period > 0 ? period : 1.0) {}
  bool master_identity(MasterIdentity* identity) const;
  void snapshot();
  bool register_all();
  std::string restore_params(bool publishes_clock);

  const double poll;
  MasterIdentity identity;
  std::set<std::string> services;
  XmlRpcValue private_params;
  bool have_private_params = false;
  std::mutex mutex;
  std::condition_variable wake;
  bool stop = false;
  bool finished = false;
};

MasterWatch::MasterWatch(double poll) : state_(std::make_shared<State>(poll)) {
  state_->snapshot();
  state_->master_identity(&state_->identity);
  thread_ = std::thread(&MasterWatch::run, state_);
}

MasterWatch::~MasterWatch() {
  std::unique_lock<std::mutex> lock(state_->mutex);
  state_->stop = true;
  state_->wake.notify_all();
  if (state_->wake.wait_for(lock, kStopWait, [state = state_] { return state->finished; })) {
    lock.unlock();
    thread_.join();
  } else {
    lock.unlock();
    thread_.detach();  // stuck in a call to a master that does not answer: never hang the node's exit
  }
}

void MasterWatch::watch_service(const std::string& name) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->services.insert(name);
}

bool MasterWatch::State::master_identity(MasterIdentity* identity) const {
  XmlRpcValue pid;
  if (!master_call("getPid", caller_args(), &pid) || pid.getType() != XmlRpcValue::TypeInt) return false;
  XmlRpcValue args = caller_args();
  args[1] = std::string("/run_id");
  XmlRpcValue run_id;
  const bool have_run_id = master_call("getParam", args, &run_id) && run_id.getType() == XmlRpcValue::TypeString;
  identity->pid = static_cast<int>(pid);
  identity->run_id = have_run_id ? static_cast<std::string>(run_id) : "";
  return true;
}

// What the master knows of this node now: its services (roscpp keeps no public list) and
// its private parameters (a launch file's <param> inside <node>).
void MasterWatch::State::snapshot() {
  const std::string self = ros::this_node::getName();
  XmlRpcValue state;
  if (master_call("getSystemState", caller_args(), &state) && state.getType() == XmlRpcValue::TypeArray &&
      state.size() == 3 && state[2].getType() == XmlRpcValue::TypeArray) {
    XmlRpcValue& services = state[2];  // [[name, [provider, ...]], ...]
    std::lock_guard<std::mutex> lock(mutex);
    for (int i = 0; i < services.size(); ++i) {
      XmlRpcValue& entry = services[i];
      if (entry.getType() != XmlRpcValue::TypeArray || entry.size() != 2 ||
          entry[0].getType() != XmlRpcValue::TypeString || entry[1].getType() != XmlRpcValue::TypeArray)
        continue;
      for (int j = 0; j < entry[1].size(); ++j)
        if (entry[1][j].getType() == XmlRpcValue::TypeString && static_cast<std::string>(entry[1][j]) == self)
          this->services.insert(static_cast<std::string>(entry[0]));
    }
  }
  XmlRpcValue args = caller_args();
  args[1] = self;
  XmlRpcValue params;
  if (master_call("getParam", args, &params) && params.getType() == XmlRpcValue::TypeStruct && params.size() > 0) {
    private_params = params;
    have_private_params = true;
  }
}

void MasterWatch::run(std::shared_ptr<State> state) {
  bool warned = false;
  std::unique_lock<std::mutex> lock(state->mutex);
  const auto period = std::chrono::duration<double>(state->poll);
  // Polling the wall clock: the master's presence is what is watched, not ROS time.
  while (!state->wake.wait_for(lock, period, [&state] { return state->stop; })) {
    lock.unlock();
    try {
      MasterIdentity identity;
      if (ros::isShuttingDown()) {
      } else if (!state->master_identity(&identity)) {
        // No master now: wait for one. Only a new master (pid, run_id) is acted on.
      } else if (same_master(state->identity, identity)) {
        state->identity = identity;  // with the run_id roslaunch has set since
      } else {
        if (state->register_all()) {
          state->identity = identity;
          warned = false;
        } else if (!warned) {
          ROS_WARN("master_watch: could not register everything with the new master yet; trying again every %g s",
                   state->poll);
          warned = true;
        }
      }
    } catch (const std::exception& e) {  // the watch must never take the node down
      if (!warned) ROS_WARN("master_watch: %s", e.what());
      warned = true;
    }
    lock.lock();
  }
  state->finished = true;
  state->wake.notify_all();
}

bool MasterWatch::State::register_all() {
  const std::string self = ros::this_node::getName();
  const std::string node_uri = ros::XMLRPCManager::instance()->getServerURI();
  bool ok = true;
  const auto publications = topic_list("getPublications");
  for (const auto& topic : publications) {
    XmlRpcValue args = caller_args(), ignored;
    args[1] = topic.first;
    args[2] = topic.second;
    args[3] = node_uri;
    ok = master_call("registerPublisher", args, &ignored) && ok;
  }
  const auto subscriptions = topic_list("getSubscriptions");
  for (const auto& topic : subscriptions) {
    XmlRpcValue args = caller_args(), publishers;
    args[1] = topic.first;
    args[2] = topic.second;
    args[3] = node_uri;
    if (!master_call("registerSubscriber", args, &publishers) || publishers.getType() != XmlRpcValue::TypeArray) {
      ok = false;
      continue;
    }
    // Tell the subscription about publishers the new master knew before it: what the master
    // does itself for the subscribers it knows when a publisher registers. roscpp drops the
    // links an update leaves out, so the live ones go in too.
    std::set<std::string> all = connected_publishers(topic.first);
    bool news = false;
    for (int i = 0; i < publishers.size(); ++i)
      if (publishers[i].getType() == XmlRpcValue::TypeString)
        news = all.insert(static_cast<std::string>(publishers[i])).second || news;
    if (!news) continue;
    XmlRpcValue update, ignored;
    update[0] = std::string("/master");
    update[1] = topic.first;
    update[2].setSize(0);
    int i = 0;
    for (const auto& uri : all) update[2][i++] = uri;
    ok = node_call("publisherUpdate", update, &ignored) && ok;
  }
  std::set<std::string> names;
  {
    std::lock_guard<std::mutex> lock(mutex);
    names = services;
  }
  const std::string service_uri = "rosrpc://" + ros::network::getHost() + ":" +
                                  std::to_string(ros::ConnectionManager::instance()->getTCPPort());
  int registered_services = 0;
  for (const auto& name : names) {
    const ros::ServicePublicationPtr service = ros::ServiceManager::instance()->lookupServicePublication(name);
    if (!service || service->isDropped()) continue;  // shut down since
    XmlRpcValue args = caller_args(), ignored;
    args[1] = name;
    args[2] = service_uri;
    args[3] = node_uri;
    const bool registered = master_call("registerService", args, &ignored);
    ok = registered && ok;
    registered_services += registered ? 1 : 0;
  }
  bool publishes_clock = false;
  for (const auto& topic : publications) publishes_clock = publishes_clock || topic.first == "/clock";
  const std::string restored = restore_params(publishes_clock);
  // Only once everything is in: a partial attempt is retried whole on the next poll (the
  // caller warns once), and one restart is one message.
  if (ok)
    ROS_INFO("master_watch: new master at %s: registered %zu publishers, %zu subscribers, %d services again%s",
             ros::master::getURI().c_str(), publications.size(), subscriptions.size(), registered_services,
             restored.empty() ? "" : ("; restored " + restored).c_str());
  return ok;
}

// Put back what a launch had set for this node, only where the new master has nothing: its
// private parameters, and /use_sim_time if the node is the clock (a node that only runs on
// sim time does not: it may be the one waiting for a /clock that is gone).
std::string MasterWatch::State::restore_params(bool publishes_clock) {
  std::string restored;
  auto restore = [&restored](const std::string& name, const XmlRpcValue& value) {
    XmlRpcValue args = caller_args(), present, ignored;
    args[1] = name;
    if (!master_call("hasParam", args, &present) || present.getType() != XmlRpcValue::TypeBoolean ||
        static_cast<bool>(present))
      return;
    args[2] = value;
    if (master_call("setParam", args, &ignored)) restored += (restored.empty() ? "" : ", ") + name;
  };
  if (have_private_params) restore(ros::this_node::getName(), private_params);
  if (publishes_clock && ros::Time::isSimTime()) restore("/use_sim_time", XmlRpcValue(true));
  return restored;
}

}  // namespace rosbook_env
