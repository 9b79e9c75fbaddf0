#!/usr/bin/python3
"""turtlebot_teleop's keyboard teleop: u i o / j k l / m , . drive, q/z w/x e/c change speeds.

Publishes geometry_msgs/Twist on `cmd_vel` at ~rate Hz (10) whether or not keys arrive, so a
command mux's 1 s timeout never stops a robot while a key is held.
Private parameters: ~speed (0.2 m/s), ~turn (1.0 rad/s), ~linear_accel (0.2 m/s^2),
~angular_accel (1.0 rad/s^2), ~key_timeout (0.75 s without a movement key: stop smoothly),
~rate (10 Hz).
"""

import sys

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.params import ParamError, positive
from teleop_bot.keyboard_teleop import HELP, KeyboardTeleop, status_line
from teleop_bot.terminal import KeyReader, NotATerminal, cbreak_terminal


def read_params():
    def get(name, default):
        return positive("~" + name, rospy.get_param("~" + name, default))

    return {
        "speed": get("speed", 0.2),
        "turn": get("turn", 1.0),
        "linear_accel": get("linear_accel", 0.2),
        "angular_accel": get("angular_accel", 1.0),
        "key_timeout": get("key_timeout", 0.75),
    }


def say(text):
    # cbreak mode keeps output post-processing, so plain newlines are fine.
    print(text, flush=True)


def run(teleop, pub, fd, hz):
    reader = KeyReader(fd)
    period = 1.0 / hz
    last = rospy.get_time()
    next_tick = last + period
    say(HELP)
    say(status_line(teleop.speed, teleop.turn))
    while not rospy.is_shutdown() and not teleop.quit:
        # Wait for keys until the next tick (wall clock for the terminal, ROS time for output).
        for key in reader.read(max(0.0, min(period, next_tick - rospy.get_time()))):
            text = teleop.on_key(key, rospy.get_time())
            if text:
                say(text)
        now = rospy.get_time()
        if now < next_tick:
            continue
        twist = Twist()
        twist.linear.x, twist.angular.z = teleop.step(now, now - last)
        pub.publish(twist)
        last = now
        next_tick = max(next_tick + period, now + 0.5 * period)
    pub.publish(Twist())


def main():
    if not sys.stdin.isatty():
        print(
            "keyboard_teleop.py: standard input is not a terminal (TTY); run it in a terminal "
            '(roslaunch: output="screen", roslaunch in the foreground)',
            file=sys.stderr,
        )
        return 1
    rospy.init_node("turtlebot_teleop_keyboard")
    survive_master_restart()  # re-registers with a restarted roscore
    try:
        params = read_params()
        hz = positive("~rate", rospy.get_param("~rate", 10.0))
    except ParamError as error:
        rospy.logfatal(str(error))
        return 2
    pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    teleop = KeyboardTeleop(**params)
    fd = sys.stdin.fileno()
    try:
        with cbreak_terminal(fd):
            run(teleop, pub, fd, hz)
    except NotATerminal as error:
        print(f"keyboard_teleop.py: {error}", file=sys.stderr)
        return 1
    except (KeyboardInterrupt, EOFError, rospy.ROSInterruptException):
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
