from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(
    **generate_distutils_setup(
        packages=["bullet_turtlebot", "bullet_turtlebot.world_families"],
        package_dir={"": "src"},
    )
)
