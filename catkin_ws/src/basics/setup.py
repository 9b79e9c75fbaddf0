"""Installs the ROS-free helpers in src/basics next to the generated basics.msg/basics.srv."""

from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["basics"], package_dir={"": "src"}))
