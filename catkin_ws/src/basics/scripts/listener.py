#!/usr/bin/python3
"""listener: logs every string that arrives on `chatter` (chapter 2)."""

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import String


def callback(msg):
    rospy.loginfo("%s I heard %s", rospy.get_caller_id(), msg.data)


def main():
    rospy.init_node("listener")
    survive_master_restart()  # re-registers with a restarted roscore
    rospy.Subscriber("chatter", String, callback)
    rospy.spin()


if __name__ == "__main__":
    main()
