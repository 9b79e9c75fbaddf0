import sys
from pathlib import Path

# The package's ROS-free module, without a catkin build.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))
