# The map-file writer's library alone: rosbook_env_LIBRARIES also holds MasterWatch and,
# through it, roscpp, which the packages' ROS-free libraries must not link.
set(rosbook_env_MAP_FILES_LIBRARIES ${rosbook_env_LIBRARIES})
list(FILTER rosbook_env_MAP_FILES_LIBRARIES INCLUDE REGEX "rosbook_map_files")

# How the workspace builds its gtests (targets catkin did not make, without gtest, are skipped):
# - at -O1: a test file's own code runs for milliseconds, and what it tests is built in the
#   package's libraries at the build type's level; -O3 doubles a test file's compile time;
# - with one precompiled <gtest/gtest.h> per package where it pays: parsing it costs some
#   1.2 CPU s a file, making the precompiled header about three times that.
function(rosbook_configure_gtests)
  set(made "")
  foreach(test_target ${ARGN})
    if(TARGET ${test_target})
      list(APPEND made ${test_target})
      target_compile_options(${test_target} PRIVATE -O1)
    endif()
  endforeach()
  list(LENGTH made count)
  if(count LESS 5)
    return()
  endif()
  list(POP_FRONT made owner)
  target_precompile_headers(${owner} PRIVATE <gtest/gtest.h>)
  foreach(test_target ${made})
    target_precompile_headers(${test_target} REUSE_FROM ${owner})
  endforeach()
endfunction()
