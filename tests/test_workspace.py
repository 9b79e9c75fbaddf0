"""The workspace's environment: Debian's Python wins over pyenv, roscore starts, topics flow."""

import os
import subprocess
from pathlib import Path


def test_python3_is_debian_after_sourcing(tmp_path):
    env = dict(os.environ, PATH="/root/.pyenv/shims:" + os.environ["PATH"])
    env.pop("PYENV_VERSION", None)
    done = subprocess.run(
        [
            "bash",
            "-c",
            "source catkin_ws/devel/setup.bash && "
            "python3 -c 'import rospy, sys; print(sys.executable)'",
        ],
        env=env,
        capture_output=True,
        text=True,
        cwd=os.path.dirname(os.path.dirname(__file__)) or ".",
    )
    assert done.returncode == 0, done.stderr
    assert os.path.samefile(done.stdout.strip(), "/usr/bin/python3"), done.stdout


def test_probe_records_a_published_message(ros):
    pub = ros.start(["rostopic", "pub", "-r", "10", "/probe_check", "std_msgs/Int32", "data: 7"])
    ros.wait_for_topic("probe_check")
    messages = ros.echo("probe_check", count=2)
    assert [m["msg"]["data"] for m in messages] == [7, 7]
    assert pub.poll() is None


SHELL_CALLS = ("shell=True", "os.system(", "os.popen(", "std::system(", "popen(")


def test_no_node_or_tool_runs_a_shell():
    """Nodes and tools (not their tests) never hand a command line to a shell: arguments and
    parameters from the user must not become shell code."""
    src = Path(__file__).resolve().parent.parent / "catkin_ws" / "src"
    offenders = []
    for path in src.glob("*/**/*"):
        rel = path.relative_to(src)
        if (
            not path.is_file()
            or "test" in rel.parts
            or path.suffix not in {"", ".py", ".cpp", ".h"}
        ):
            continue
        try:
            text = path.read_text()
        except (UnicodeDecodeError, OSError):
            continue  # binary
        offenders += [f"{rel}: {call}" for call in SHELL_CALLS if call in text]
    assert not offenders, offenders
