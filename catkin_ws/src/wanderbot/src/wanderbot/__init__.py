"""ROS-free decision logic for the wanderbot nodes (chapter 7)."""
