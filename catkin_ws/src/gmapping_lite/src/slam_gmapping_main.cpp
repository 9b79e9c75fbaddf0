// slam_gmapping's main: start the node (SlamGmappingNode, slam_gmapping_node.h) and spin.
#include <ros/ros.h>
#include <rosbook_env/master_watch.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "slam_gmapping_node.h"

int main(int argc, char** argv) {
  // Diagnostics appear line by line even when stdout is a file or a pipe.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "slam_gmapping");
  std::unique_ptr<gmapping_lite::SlamGmappingNode> node;
  try {
    node = std::make_unique<gmapping_lite::SlamGmappingNode>();
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const rosbook_env::MasterWatch master_watch;  // re-registers with a restarted roscore
  // Two threads: the service and the scan callback must not block each other for long.
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
