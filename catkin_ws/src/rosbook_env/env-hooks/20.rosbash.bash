# Sourced by devel/setup.bash and install/setup.bash (bash only). The book uses roscd, rosls,
# rosed and tab completion of package names right after sourcing a setup.bash, as
# /opt/ros/<distro>/setup.bash provided them. Debian installs those functions only as a
# bash-completion file, which an interactive shell loads lazily, on the first completion of
# a ros* command; and rosbash's own catkin hook is not sourced without /opt/ros. Load them
# here (they define functions and `complete` rules, nothing else).
if [ -r /usr/share/bash-completion/completions/rosbash ]; then
  . /usr/share/bash-completion/completions/rosbash
elif [ -r /usr/share/rosbash/rosbash ]; then
  . /usr/share/rosbash/rosbash
fi
