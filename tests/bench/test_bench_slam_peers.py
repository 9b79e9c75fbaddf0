"""bench_slam_peers' plumbing on real processes: the real slam_gmapping, which seeds itself
with time(NULL), gets the run's seed from bench/gmapping_seed.c preloaded into it (built as
the bench builds it, time() then returns $GMAPPING_SEED, and libc's time without it); and the
wait after the playback ends when the nodes go idle."""

import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_script import load_bench_script  # noqa: E402

# time(NULL) as a C program calls it, from a Python child (ctypes calls libc's symbol through
# the dynamic linker, so a preloaded time() takes its place as it does in slam_gmapping).
CALL_TIME = "import ctypes; print(ctypes.CDLL(None).time(None))"


bench = load_bench_script("bench_slam_peers")


def time_in(env):
    done = subprocess.run(
        ["/usr/bin/python3", "-c", CALL_TIME], env=env, capture_output=True, text=True, check=True
    )
    return int(done.stdout.strip())


def test_preloaded_time_returns_the_seed(tmp_path):
    lib = bench.seed_library(tmp_path)
    env = bench.peer_environment({"PATH": "/usr/bin:/bin"}, tmp_path / "ws", lib, 7)
    assert env["GMAPPING_SEED"] == "7"
    assert env["LD_PRELOAD"] == str(lib)
    assert env["LD_LIBRARY_PATH"].startswith(f"{tmp_path / 'ws'}/devel/lib:")
    assert time_in(env) == 7
    assert time_in({**env, "GMAPPING_SEED": "1795817010"}) == 1795817010


def test_without_a_seed_time_is_libcs(tmp_path):
    lib = bench.seed_library(tmp_path)
    env = {"PATH": "/usr/bin:/bin", "LD_PRELOAD": str(lib)}
    # The clock's seconds, not a seed: well past the seeds a bench run uses.
    assert time_in(env) > 1_000_000_000


def test_an_existing_preload_is_kept(tmp_path):
    env = bench.peer_environment({"LD_PRELOAD": "libother.so"}, tmp_path, "libseed.so", 3)
    assert env["LD_PRELOAD"] == "libseed.so libother.so"


def test_seed_zero_is_refused():
    with pytest.raises(SystemExit) as refused:
        bench.parse_args(["--stage-seeds", "0,1"])
    assert refused.value.code == 2


def test_waiting_for_the_nodes_ends_when_they_are_idle():
    idle = subprocess.Popen(["sleep", "60"])
    busy = subprocess.Popen(["/usr/bin/python3", "-c", "while True: pass"])
    try:
        assert bench.wait_until_idle([idle.pid], timeout=20)
        assert not bench.wait_until_idle([idle.pid, busy.pid], timeout=4)
    finally:
        for proc in (idle, busy):
            proc.kill()
            proc.wait()
