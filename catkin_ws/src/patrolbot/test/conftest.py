import sys
from pathlib import Path

# The package's ROS-free module and rosbook_env (its YAML loader), without a catkin build.
PACKAGE = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(PACKAGE / "src"), str(PACKAGE.parent / "rosbook_env" / "src")]
