"""The screenshot helper's pure parts (no X server, no ROS): finding rviz's render
windows in xwininfo's tree, and the colour measurements the view tests rely on."""

import signal
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from rviz_checks import rs  # noqa: E402

# Trimmed from a real `xwininfo -root -tree` of rviz 1.14 with two Image displays.
TREE = """
  Root window id: 0x50d (the root window) (has no name)
     4 children:
     0x200010 "teleop.rviz - RViz": ("rviz" "rviz")  1280x800+0+0  +0+0
        8 children:
        0x200127 "rviz": ("rviz" "rviz")  1280x40+0+22  +0+22
        0x200115 "rviz": ("rviz" "rviz")  342x143+0+211  +0+211
           0x200113 "rviz": ("rviz" "rviz")  342x121+0+22  +0+233
              1 child:
              0x600008 (has no name): ()  342x121+0+0  +0+233
        0x20010b "rviz": ("rviz" "rviz")  342x143+0+62  +0+62
              0x600006 (has no name): ()  342x121+0+0  +0+84
           0x200016 "rviz": ("rviz" "rviz")  900x709+16+0  +364+62
              1 child:
              0x600004 (has no name): ()  900x709+0+0  +364+62
     0x400001 (has no name): ()  1x1+0+0  +0+0
"""


def test_render_windows_are_the_unnamed_ones_largest_first():
    assert rs.parse_ogre_windows(TREE) == [
        (364, 62, 900, 709),
        (0, 233, 342, 121),
        (0, 84, 342, 121),
    ]
    assert rs.parse_ogre_windows("") == []


def test_hsv_of_primaries_and_greys():
    img = np.array([[[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 0, 255], [48, 48, 48]]])
    hue, sat, val = rs.hsv(img.astype(np.uint8))
    assert hue[0, :4].tolist() == pytest.approx([0, 120, 240, 300])
    assert sat[0].tolist() == pytest.approx([1, 1, 1, 1, 0])
    assert val[0, 4] == pytest.approx(48 / 255) and np.isnan(hue[0, 4])


def test_masks_counts_centroid_extent():
    img = np.full((10, 20, 3), 48, dtype=np.uint8)
    img[2:4, 5:15] = (219, 148, 76)  # a tan bar, 2 × 10 px
    mask = rs.mask_hsv(img, hue=(15, 45), sat=(0.3, 0.9))
    assert int(mask.sum()) == 20
    assert rs.count_rgb(img, (219, 148, 76), tol=0) == 20
    assert rs.count_hsv(img, hue=(330, 10)) == 0  # a wrapping range (reds); greys never match
    assert rs.centroid(mask) == pytest.approx((9.5, 2.5))
    assert rs.extent(mask) == (10, 2)
    empty = np.zeros((3, 3), bool)
    assert rs.centroid(empty) is None and rs.extent(empty) == (0, 0)
    assert rs.is_blank(np.full((4, 4, 3), 48, np.uint8)) and not rs.is_blank(img)
    assert rs.crop(img, (5, 2, 10, 2)).shape == (2, 10, 3)


def test_missing_config_is_a_clear_error(tmp_path):
    with pytest.raises(FileNotFoundError, match="rviz config not found"):
        rs.RvizSession(tmp_path / "nope.rviz")


class _FlakyGrabs(rs.RvizSession):
    """A session whose screen grabs follow a script (no X server): an exception to raise or
    a picture to return, one per grab."""

    def __init__(self, grabs):  # nothing of the real session is started
        self.grabs = list(grabs)

    def shot(self, out=None):
        grab = self.grabs.pop(0)
        if isinstance(grab, Exception):
            raise grab
        return Path("shot.png"), grab


def test_settle_grabs_again_after_a_failed_grab():
    picture = np.full((4, 4, 3), 200, dtype=np.uint8)
    failed = rs.ScreenGrabError("import failed: XIO: fatal IO error 11")
    session = _FlakyGrabs([failed, failed, picture])
    path, img = session.settle(lambda img: img.mean() > 100, timeout=30, interval=0, min_wait=0)
    assert img is picture and session.grabs == []


def test_settle_gives_up_on_grabs_at_the_deadline_naming_the_error():
    failed = rs.ScreenGrabError("import failed: XIO: fatal IO error 11")
    session = _FlakyGrabs([failed] * 3)
    with pytest.raises(rs.ScreenGrabError, match="fatal IO error 11"):
        session.settle(lambda img: True, timeout=-1, interval=0, min_wait=0)
    assert len(session.grabs) == 2  # no grab after the deadline had passed


def test_settle_stops_at_once_when_rviz_is_gone():
    session = _FlakyGrabs([rs.RvizError("rviz is not running"), np.zeros((2, 2, 3))])
    with pytest.raises(rs.RvizError, match="not running"):
        session.settle(lambda img: True, timeout=30, interval=0, min_wait=0)


def test_crash_signal_reads_roslaunch_and_xvfb_run():
    died = "process has died [pid 14230, exit code -11, cmd /usr/lib/rviz/rviz -d x.rviz]"
    assert rs.crash_signal(0, died) == signal.SIGSEGV
    assert rs.crash_signal(128 + signal.SIGABRT, "") == signal.SIGABRT
    assert rs.crash_signal(1, "process has died [pid 3, exit code -15, cmd rviz]") is None
    assert rs.crash_signal(0, "") is None and rs.crash_signal(None, "") is None


class _CrashingSession(_FlakyGrabs):
    """Grabs follow a script; start and close only count."""

    def __init__(self, grabs):
        super().__init__(grabs)
        self.starts = 0

    def start(self, attempts=3):
        self.starts += 1

    def close(self):
        pass


def test_settle_starts_rviz_again_once_after_a_crash_at_start_up():
    picture = np.full((4, 4, 3), 200, dtype=np.uint8)
    crashed = rs.RvizCrashed("rviz is not running (SIGSEGV)")
    session = _CrashingSession([crashed, picture])
    path, img = session.settle(lambda img: True, timeout=30, interval=0, min_wait=0)
    assert img is picture and session.starts == 1
    session = _CrashingSession([crashed, crashed, picture])  # a second crash is a failure
    with pytest.raises(rs.RvizCrashed):
        session.settle(lambda img: True, timeout=30, interval=0, min_wait=0)
    assert session.starts == 1
