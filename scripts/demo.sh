#!/usr/bin/env bash
# The main job: a simulated Turtlebot explores the office world while gmapping_lite maps it,
# headless and faster than real time. Writes out/office_map.{pgm,yaml}, out/office_overlay.png
# and out/figures.json, and prints the accuracy figures. Arguments go to mapping_demo
# (e.g. --live for real time with rviz, --world maze, --sim-seconds 600).
set -eo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/scripts/python-env.sh"
source "$here/catkin_ws/devel/setup.bash"
cd "$here"
exec rosrun rosbook_demo mapping_demo --out "$here/out" "$@"
