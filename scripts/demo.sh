#!/usr/bin/env bash
# The main job. Until the simulator and SLAM land: the chapter 3-5 demo.
set -eo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/scripts/python-env.sh"
source "$here/catkin_ws/devel/setup.bash"
echo "demo: not yet available (the chapter demos land with the basics package)" >&2
exit 1
