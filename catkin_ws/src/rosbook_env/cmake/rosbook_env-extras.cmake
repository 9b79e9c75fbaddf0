# The map-file writer's library alone: rosbook_env_LIBRARIES also holds MasterWatch and,
# through it, roscpp, which the packages' ROS-free libraries must not link.
set(rosbook_env_MAP_FILES_LIBRARIES ${rosbook_env_LIBRARIES})
list(FILTER rosbook_env_MAP_FILES_LIBRARIES INCLUDE REGEX "rosbook_map_files")
