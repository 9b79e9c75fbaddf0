"""map_server and map_saver for rosbook-one: map files (map_io) and the ROS nodes' helpers."""
