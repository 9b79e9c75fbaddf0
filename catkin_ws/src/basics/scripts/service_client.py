#!/usr/bin/python3
"""service_client: counts its command-line words with the `word_count` service (chapter 4).

    rosrun basics service_client.py these are some words
    these are some words -> 4

Waits for the service to be advertised if the server is not running yet.
"""

import sys

import rospy
from basics.srv import WordCount
from basics.words import format_count

USAGE = "usage: service_client.py WORD... (prints 'WORD... -> number of words')"


def main():
    argv = rospy.myargv()[1:]
    if argv in (["-h"], ["--help"]):
        print(USAGE)
        return 0
    words = " ".join(argv)

    rospy.init_node("service_client")
    service = rospy.resolve_name("word_count")
    try:
        rospy.wait_for_service(service, timeout=1.0)
    except rospy.ROSException:
        rospy.loginfo("waiting for the service %s to be advertised", service)
        rospy.wait_for_service(service)
    word_counter = rospy.ServiceProxy(service, WordCount)
    try:
        word_count = word_counter(words)
    except rospy.ServiceException as err:
        print(f"service_client: the call to {service} failed: {err}", file=sys.stderr)
        return 1
    print(format_count(words, word_count.count), flush=True)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except rospy.ROSInterruptException:
        sys.exit(1)
