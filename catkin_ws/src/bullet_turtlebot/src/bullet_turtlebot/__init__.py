"""World generation for the simulator (the messages live in bullet_turtlebot.msg)."""

from pkgutil import extend_path

# The generated messages sit in the devel space's bullet_turtlebot package; merging the
# package paths keeps bullet_turtlebot.msg importable when this source directory comes first.
__path__ = extend_path(__path__, __name__)
