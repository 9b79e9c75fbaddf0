"""bench/results_section.py on text: a section is replaced whole, or, with keep_subsections,
only the '### ' subsections the new text brings (bench_slam_worlds' per-laser tables)."""

import sys
from pathlib import Path
from types import SimpleNamespace

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_script import BENCH, load_bench_script  # noqa: E402

sys.path.insert(0, str(BENCH))
from results_section import merge_subsections, split_subsections, write_section  # noqa: E402

RESULTS = """\
# Results

## Other benchmark

untouched

## SLAM worlds

Old method text.

### Kinect

old kinect table

### Wide laser

wide table from an earlier run

## Last benchmark

also untouched
"""


def test_split_subsections():
    preamble, subs = split_subsections(["## S", "", "text", "### A", "a", "#### deeper", "### B"])
    assert preamble == ["## S", "", "text"]
    assert subs == [("### A", ["a", "#### deeper"]), ("### B", [])]


def test_keep_subsections_replaces_only_the_ones_brought(tmp_path):
    path = tmp_path / "RESULTS.md"
    path.write_text(RESULTS)
    write_section(
        path,
        ["## SLAM worlds", "", "New method text.", "", "### Kinect", "", "new kinect"],
        keep_subsections=True,
    )
    assert path.read_text() == RESULTS.replace("Old method text.", "New method text.").replace(
        "old kinect table", "new kinect"
    )


def test_new_subsections_follow_the_kept_ones():
    old = ["## S", "", "### Wide", "", "wide rows", ""]
    new = ["## S", "", "intro", "", "### Kinect", "", "kinect rows", ""]
    assert merge_subsections(old, new) == (
        ["## S", "", "intro", "", "### Wide", "", "wide rows", "", "### Kinect", "", "kinect rows"]
    )


def test_without_keep_subsections_the_section_is_replaced_whole(tmp_path):
    path = tmp_path / "RESULTS.md"
    path.write_text(RESULTS)
    write_section(path, ["## SLAM worlds", "", "### Kinect", "", "new kinect"])
    text = path.read_text()
    assert "wide table from an earlier run" not in text and "new kinect" in text
    assert "untouched" in text and "also untouched" in text


def test_a_section_not_there_yet_is_appended(tmp_path):
    path = tmp_path / "RESULTS.md"
    write_section(path, ["## New", "", "### Kinect", "", "rows"], keep_subsections=True)
    assert path.read_text() == "## New\n\n### Kinect\n\nrows\n"


def load_bench_slam_worlds():
    return load_bench_script("bench_slam_worlds")


def test_a_kinect_only_run_keeps_the_wide_laser_subsection(tmp_path):
    """`bench_slam_worlds --results F --lasers kinect` after a run of both lasers."""
    bench = load_bench_slam_worlds()
    row = dict(
        world="ring_1",
        family="ring",
        slam="live, Turtlebot tuning",
        travelled=100.0,
        ate=0.5,
        ate_start=0.7,
        walls=0.5,
        walls_start=0.4,
        coverage=0.9,
        cpu=80.0,
        note="",
    )

    def run(lasers, ate):
        args = SimpleNamespace(
            lasers=lasers, families=["ring"], seeds=[1], sim_seconds=900.0, speed=5.0
        )
        rows = [dict(row, laser=laser, ate=ate) for laser in lasers]
        failures = [(laser, f"ring_2 ({laser}, live)") for laser in lasers]
        write_section(path, bench.section(rows, args, failures), keep_subsections=True)

    path = tmp_path / "RESULTS.md"
    run(["kinect", "wide"], ate=0.5)
    run(["kinect"], ate=0.25)
    text = path.read_text()
    _, subs = split_subsections(text.splitlines())
    bodies = {heading: "\n".join(body) for heading, body in subs}
    kinect = f"### {bench.LASERS['kinect']['label']}"
    wide = f"### {bench.LASERS['wide']['label']}"
    assert list(bodies) == [kinect, wide]
    assert "| 0.250 |" in bodies[kinect] and "| 0.500 |" not in bodies[kinect]
    assert "| wide |" in bodies[wide] and "| 0.500 |" in bodies[wide]
    assert "Failed: ring_2 (wide, live)." in bodies[wide]
    assert "(wide" not in bodies[kinect]
