#!/usr/bin/env bash
# Run every test: C++ gtests, Python unit tests and the ROS integration tests (real roscore,
# real nodes, rostest). Ends with pytest's summary line; exits non-zero on any failure.
# Extra arguments go to pytest (e.g. scripts/test.sh -k basics).
set -eo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/scripts/python-env.sh"
source "$here/catkin_ws/devel/setup.bash"
cd "$here"
shopt -s nullglob
unit_dirs=(catkin_ws/src/*/test)
# Two workers per core: most of a test is waiting (process start-up, roscore, simulations
# that run at a set speed), so with three workers on two cores the load stayed near 1; and the
# tests do not depend on load (sim time, held clocks).
workers=${ROSBOOK_TEST_WORKERS:-$((2 * $(nproc)))}
# --dist loadscope: whole modules to a worker, longest first (tests/conftest.py says why).
exec /usr/bin/python3 -m pytest -n "$workers" --dist loadscope tests "${unit_dirs[@]}" "$@"
