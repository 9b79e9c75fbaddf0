"""roscd, rosls and tab completion come with `source catkin_ws/devel/setup.bash`, as the book
expects (rosbook_env's env hook sources Debian's rosbash functions). No ROS master needed."""

import os
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
BASICS = REPO / "catkin_ws" / "src" / "basics"


def in_fresh_bash(script):
    """Run `script` in a non-interactive bash that has only sourced devel/setup.bash."""
    env = {"HOME": os.environ.get("HOME", "/root"), "PATH": "/usr/local/bin:/usr/bin:/bin"}
    done = subprocess.run(
        ["bash", "-c", "source catkin_ws/devel/setup.bash && " + script],
        env=env,
        capture_output=True,
        text=True,
        cwd=REPO,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_roscd_goes_to_the_package():
    assert in_fresh_bash("roscd basics && pwd").strip() == str(BASICS)
    assert in_fresh_bash("roscd basics/scripts && pwd").strip() == str(BASICS / "scripts")


def test_rosls_lists_the_package():
    listed = in_fresh_bash("rosls basics").split()
    assert {"package.xml", "scripts", "msg", "launch"} <= set(listed)


def test_tab_completion_of_package_and_script_names():
    # What bash runs on `roscd bas<TAB>` and `rosrun basics topic_p<TAB>`.
    roscd = in_fresh_bash(
        "complete -p roscd >&2 && COMP_WORDS=(roscd bas) COMP_CWORD=1 && "
        '_roscomplete_sub_dir && printf "%s\\n" "${COMPREPLY[@]}"'
    )
    assert set(roscd.split()) == {"basics/"}
    rosrun = in_fresh_bash(
        "COMP_WORDS=(rosrun basics topic_p) COMP_CWORD=2 && "
        '_roscomplete_exe && printf "%s\\n" "${COMPREPLY[@]}"'
    )
    assert set(rosrun.split()) == {"topic_publisher.py"}


def test_rviz_media_lookup_finds_the_media_export_package():
    # rviz runs this at start-up; without a media_export package rospack prints
    # "[rospack] Error: no such package media_export" (catkin_ws/src/media_export).
    done = subprocess.run(
        ["rospack", "plugins", "--attrib=ogre_media_path", "media_export"],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0 and "Error" not in done.stderr, done.stderr
