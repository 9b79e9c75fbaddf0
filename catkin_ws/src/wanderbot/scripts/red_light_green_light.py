#!/usr/bin/python3
"""Drive forward at 0.5 m/s for 3 s, stop for 3 s, repeat (publishes cmd_vel at 10 Hz)."""

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.sim_time import warn_if_no_clock
from wanderbot.behaviours import TrafficLight


def main():
    rospy.init_node("red_light_green_light")
    survive_master_restart()  # re-registers with a restarted roscore
    warn_if_no_clock()  # says so if /use_sim_time waits for a /clock that never comes
    cmd_vel_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)

    red_light_twist = Twist()
    green_light_twist = Twist()
    green_light_twist.linear.x = 0.5  # drive straight ahead at 0.5 m/s

    rate = rospy.Rate(10, reset=True)  # reset: survive sim time jumping back
    wait_for_clock()
    light = TrafficLight(rospy.get_time(), period=3.0)
    rospy.on_shutdown(lambda: cmd_vel_pub.publish(red_light_twist))
    while not rospy.is_shutdown():
        driving_forward = light.update(rospy.get_time())
        cmd_vel_pub.publish(green_light_twist if driving_forward else red_light_twist)
        rate.sleep()


def wait_for_clock():
    """Under sim time, rospy time is 0 until /clock arrives; timing from 0 would be wrong."""
    while not rospy.is_shutdown() and rospy.get_rostime().is_zero():
        rospy.sleep(0.01)


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
