"""ROS-free parts of the rqt_plot and rqt_graph stand-ins."""
