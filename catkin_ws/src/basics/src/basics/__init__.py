"""basics: chapters 2-5 of Programming Robots with ROS.

This source package holds ROS-free helpers (words, timer); catkin merges it with the
generated message modules, so `from basics.msg import Complex` and
`from basics.words import count_words` both work once devel/setup.bash is sourced.
"""
