"""ROS-free logic of the chapter 8 teleoperation nodes."""
