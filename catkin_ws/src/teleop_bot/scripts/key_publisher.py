#!/usr/bin/python3
"""Keyboard driver: publish every key typed in this terminal as std_msgs/String on `keys`."""

import sys

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import String
from teleop_bot.terminal import KeyReader, NotATerminal, cbreak_terminal


def main():
    fd = sys.stdin.fileno()
    if not sys.stdin.isatty():
        print(
            "key_publisher.py: standard input is not a terminal (TTY); "
            "run it in a terminal window to read keystrokes",
            file=sys.stderr,
        )
        return 1
    rospy.init_node("keyboard_driver")
    survive_master_restart()  # re-registers with a restarted roscore
    key_pub = rospy.Publisher("keys", String, queue_size=10)
    reader = KeyReader(fd)
    try:
        with cbreak_terminal(fd):
            print("Publishing keystrokes. Press Ctrl-C to exit...", flush=True)
            while not rospy.is_shutdown():
                # A short wait instead of a busy poll keeps ROS callbacks and Ctrl-C responsive.
                for key in reader.read(0.05):
                    key_pub.publish(key)
    except NotATerminal as error:
        print(f"key_publisher.py: {error}", file=sys.stderr)
        return 1
    except (KeyboardInterrupt, EOFError):
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
