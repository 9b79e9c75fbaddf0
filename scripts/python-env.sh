# Sourced: make python3 Debian's, even when a pyenv shim comes first on PATH (pyenv's
# python3 cannot import catkin_pkg or rospy).
export PYENV_VERSION=system
