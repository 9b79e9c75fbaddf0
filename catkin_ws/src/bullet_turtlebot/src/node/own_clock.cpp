#include "own_clock.hpp"

#include <ros/master.h>
#include <ros/this_node.h>

namespace bullet_turtlebot {

std::vector<char*> argv_with_own_clock(int argc, char** argv, std::string* storage) {
  *storage = std::string("/use_sim_time:=") + kRoscppUseSimTime;
  std::vector<char*> out(argv, argv + argc);
  out.push_back(storage->data());
  out.push_back(nullptr);
  return out;
}

OwnClock::OwnClock() {
  XmlRpc::XmlRpcValue request, response, value;
  request[0] = ros::this_node::getName();
  request[1] = std::string("/use_sim_time");  // the master's key itself: no remapping here
  if (ros::master::execute("getParam", request, response, value, false) &&
      value.getType() == XmlRpc::XmlRpcValue::TypeBoolean) {
    sim_time_ = static_cast<bool>(value);
  }
}

}  // namespace bullet_turtlebot
