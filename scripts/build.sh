#!/usr/bin/env bash
# Build the catkin workspace (and its C++ unit tests) with Debian's Python.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/scripts/python-env.sh"
cd "$here/catkin_ws"
# A build configured with another interpreter caches its path: start afresh.
if [ -f build/CMakeCache.txt ] && ! grep -q "^PYTHON_EXECUTABLE:FILEPATH=/usr/bin/python3$" build/CMakeCache.txt; then
  echo "build: build/ was configured with another Python; removing it"
  rm -rf build devel
fi
jobs=${ROSBOOK_JOBS:-$(nproc)}
# catkin_make reconfigures whenever it is given CMake arguments (some 20 CPU s, a minute on a
# busy machine): give them only to a build that is not configured with them yet.
cmake_args=(-DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release)
if [ -f build/CMakeCache.txt ] && grep -q "^CMAKE_BUILD_TYPE:STRING=Release$" build/CMakeCache.txt; then
  cmake_args=()
fi
log=$(mktemp)
# devel space, the C++ tests, and the install space (catkin_ws/install, tested by the suite),
# in one catkin_make: each call checks the whole build system again.
if ! catkin_make -j"$jobs" "${cmake_args[@]}" all tests install >"$log" 2>&1; then
  tail -n 60 "$log"
  echo "build: FAILED (full log: $log)" >&2
  exit 1
fi
grep -E "warning:" "$log" | grep -v "byte-compiling is disabled" | sort -u | head -n 20 || true
rm -f "$log"
echo "build: OK ($here/catkin_ws/devel)"
