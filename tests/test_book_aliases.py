"""The book's package names run our packages: rospy_tutorials, turtlebot_teleop (the
simulator and gmapping aliases are exercised by tests/chapter9)."""


def test_rosrun_rospy_tutorials_talker_and_listener(ros):
    ros.start(["rosrun", "rospy_tutorials", "talker"], name="talker")
    listener = ros.start(["rosrun", "rospy_tutorials", "listener"], name="listener")
    ros.wait_for_topic("chatter")
    message = ros.echo("chatter", count=1)[0]["msg"]["data"]
    assert message.startswith("hello world")
    ros.wait_for(lambda: "hello world" in ros.output(listener), 20, "the listener to hear it")


def test_alias_launch_files_resolve_to_ours(ros):
    nodes = ros.run(["roslaunch", "--nodes", "turtlebot_teleop", "keyboard_teleop.launch"])
    assert nodes.stdout.split(), nodes.stdout
    files = ros.run(["roslaunch", "--files", "turtlebot_gazebo", "turtlebot_playground.launch"])
    assert "bullet_turtlebot/launch/simulator.launch" in files.stdout
