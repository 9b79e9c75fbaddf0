#!/usr/bin/python3
"""service_server: the `word_count` service (basics/WordCount, chapter 4).

The book shows four ways for the callback to return its answer; choose one with
`--mode` or the private parameter `~mode`: response (default, a WordCountResponse),
value (the bare count), list, tuple, or dict ({'count': n}).
"""

import argparse
import sys

import rospy
from basics.srv import WordCount, WordCountResponse
from basics.words import RETURN_MODES, count_words, shape_reply
from rosbook_env.master_watch import survive_master_restart


def main():
    parser = argparse.ArgumentParser(description="Counts the words of a string: word_count.")
    parser.add_argument(
        "--mode", choices=RETURN_MODES, help="how the callback returns (default: ~mode or response)"
    )
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node("service_server")
    survive_master_restart()  # re-registers with a restarted roscore
    mode = args.mode or rospy.get_param("~mode", "response")
    if mode not in RETURN_MODES:
        rospy.logfatal("~mode must be one of %s, got %r", ", ".join(RETURN_MODES), mode)
        sys.exit(2)

    def handle(request):
        return shape_reply(count_words(request.words), mode, WordCountResponse)

    rospy.Service("word_count", WordCount, handle)
    rospy.loginfo("word_count ready; the callback returns a %s", mode)
    rospy.spin()


if __name__ == "__main__":
    main()
