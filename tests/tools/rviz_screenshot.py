#!/usr/bin/python3
"""Run rviz headless under Xvfb, take screenshots of it, and measure colours in them.

Library use (tests):

    with RvizSession(config, env, workdir) as rviz:
        path, img = rviz.settle(lambda img: count_rgb(rviz.view(img), (255, 0, 255)) > 50)

Command line (a person's quick look, against a running master):

    tests/tools/rviz_screenshot.py CONFIG.rviz OUT.png [--wait 8] [--master http://host:11311]

rviz runs as `xvfb-run -a -s '-screen 0 1280x800x24' rviz -d CONFIG`; screenshots are
`import -window root` inside that X server.  The 3D view's rectangle is found from the
X window tree (Ogre draws into its own native child window), so colour counts can be
restricted to it and are not fooled by the panels' icons and text.
"""

import argparse
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from PIL import Image

SCREEN = (1280, 800)


class RvizError(RuntimeError):
    pass


class RvizCrashed(RvizError):
    """rviz died from a signal (a segfault inside Debian's rviz or Ogre, seen once in CI as
    rviz started under load): a crash of the viewer, not a verdict on what it shows."""


# Signals that mean a crash, not a stop: roslaunch logs "exit code -11", xvfb-run exits
# 128 + the signal of the command it ran.
CRASH_SIGNALS = (signal.SIGSEGV, signal.SIGABRT, signal.SIGBUS, signal.SIGILL, signal.SIGFPE)
_DIED = re.compile(r"process has died \[pid \d+, exit code -(\d+)")


def crash_signal(returncode, log):
    """The crash signal rviz died from, read from xvfb-run's exit code and the session's
    log (roslaunch's "process has died" line); None when it stopped otherwise."""
    codes = [int(code) for code in _DIED.findall(log)]
    if returncode is not None and returncode > 128:
        codes.append(returncode - 128)
    return next((signal.Signals(c) for c in codes if c in CRASH_SIGNALS), None)


class ScreenGrabError(RvizError):
    """One screen grab failed while rviz ran (an X error such as "fatal IO error 11" when a
    loaded machine leaves Xvfb slow to answer): the next grab may well succeed."""


def _group_running(pgid):
    """True while a process of process group `pgid` runs (zombies have ended)."""
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue  # a process that ended while we looked
        if int(fields[2]) == pgid and fields[0] != "Z":
            return True
    return False


class RvizSession:
    """One rviz inside its own Xvfb; screenshots on demand; everything killed on close.

    An rviz that crashes before its first screenshot is started again, once (RvizCrashed).
    """

    crash_restarts = 1  # how many crashes at start-up to start again after
    pictures = 0  # screenshots taken so far

    def __init__(self, config=None, env=None, workdir=None, screen=SCREEN, command=None):
        """rviz -d `config`, or any `command` that opens rviz (e.g. a roslaunch)."""
        if command is None:
            if config is None:
                raise ValueError("RvizSession needs an rviz config or a command")
            config = Path(config).resolve()
            if not config.is_file():
                raise FileNotFoundError(f"rviz config not found: {config}")
            command = ["rviz", "-d", str(config)]
        self.command = [str(part) for part in command]
        self.env = dict(env or os.environ)
        self.workdir = Path(workdir or tempfile.mkdtemp(prefix="rviz-"))
        self.workdir.mkdir(parents=True, exist_ok=True)
        self.screen = screen
        self.proc = None
        self.display = None
        self.xauthority = None
        self.rviz_pid = None
        self._shots = 0
        self._view = None

    # -- life cycle ----------------------------------------------------------------
    def __enter__(self):
        self.start()
        return self

    def __exit__(self, *exc):
        self.close()

    def start(self, attempts=3):
        """Start Xvfb + rviz; retry when `xvfb-run -a` loses a display-number race."""
        for attempt in range(attempts):
            try:
                self._start_once(attempt)
                return self
            except RvizError:
                self.close()
                if attempt == attempts - 1:
                    raise
                time.sleep(1.0)
        return self

    def _start_once(self, attempt):
        info = self.workdir / f"xvfb-{attempt}.info"
        self.log_path = self.workdir / f"rviz-{attempt}.log"
        # The inner shell reports the display and cookie file xvfb-run chose and its own
        # pid, then becomes the command (so that pid is rviz's, or roslaunch's).
        inner = 'echo "$DISPLAY $XAUTHORITY $$" > "$0.tmp" && mv "$0.tmp" "$0" && exec "$@"'
        width, height = self.screen
        cmd = [
            "xvfb-run",
            "-a",
            "-s",
            f"-screen 0 {width}x{height}x24",
            "sh",
            "-c",
            inner,
            str(info),
            *self.command,
        ]
        env = dict(self.env)
        env.pop("DISPLAY", None)
        # xvfb-run's folder (its Xauthority) in the session's own folder: xvfb-run leaves it
        # behind when it is stopped by a signal.
        env["TMPDIR"] = str(self.workdir)
        with open(self.log_path, "w") as log:
            self.proc = subprocess.Popen(
                cmd,
                stdout=log,
                stderr=subprocess.STDOUT,
                stdin=subprocess.DEVNULL,
                env=env,
                cwd=self.workdir,
                start_new_session=True,
            )
        deadline = time.monotonic() + 20
        while not info.exists():
            if self.proc.poll() is not None:
                raise RvizError("xvfb-run/rviz exited early:\n" + self.log())
            if time.monotonic() > deadline:
                raise RvizError("Xvfb did not come up within 20 s:\n" + self.log())
            time.sleep(0.05)
        self.display, self.xauthority, pid = info.read_text().split()
        self.rviz_pid = int(pid)

    def log(self):
        try:
            return Path(self.log_path).read_text(errors="replace")
        except (AttributeError, OSError):
            return ""

    def close(self):
        if self.proc is None:
            return
        # Stop rviz alone first, so xvfb-run's own clean-up stops Xvfb and removes its
        # cookie directory; then make sure nothing of the process group is left.
        if self.rviz_pid:
            try:
                os.kill(self.rviz_pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        steps = ((None, 8),) if self.rviz_pid else ()
        for sig, wait in steps + ((signal.SIGTERM, 5), (signal.SIGKILL, 3)):
            try:
                if sig is not None:
                    os.killpg(self.proc.pid, sig)
            except ProcessLookupError:
                break
            try:
                self.proc.wait(timeout=wait)
                break
            except subprocess.TimeoutExpired:
                continue
        # xvfb-run exits as soon as it has signalled Xvfb; Xvfb removes its /tmp/.X<n>-lock
        # on the way out, and a SIGKILL before then leaves the lock behind.
        deadline = time.monotonic() + 5
        while _group_running(self.proc.pid) and time.monotonic() < deadline:
            time.sleep(0.05)
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.proc = None
        self.rviz_pid = None

    # -- screenshots -------------------------------------------------------------------
    def _xenv(self):
        env = dict(self.env)
        env["DISPLAY"] = self.display
        env["XAUTHORITY"] = self.xauthority
        return env

    def shot(self, out=None):
        """Screenshot of the whole X screen; returns (path, RGB array)."""
        if self.proc is None or self.proc.poll() is not None:
            returncode = None if self.proc is None else self.proc.returncode
            crash = crash_signal(returncode, self.log())
            error = RvizCrashed if crash else RvizError
            how = crash.name if crash else "stopped"
            raise error(f"rviz is not running ({how}):\n" + self.log())
        self._shots += 1
        out = Path(out or self.workdir / f"shot-{self._shots:03d}.png")
        tmp = out.with_name(out.name + ".part.png")
        done = subprocess.run(
            ["import", "-window", "root", str(tmp)],
            env=self._xenv(),
            capture_output=True,
            text=True,
            # Xvfb serves rviz's software rendering too: on a loaded machine a large screen
            # (the willow map's) took over 20 s to grab while rviz was starting.
            timeout=60,
        )
        if done.returncode != 0:
            tmp.unlink(missing_ok=True)
            raise ScreenGrabError(f"import failed: {done.stderr.strip()}")
        os.replace(tmp, out)  # a reader never sees half a PNG
        self.pictures += 1
        self._view = None  # the layout may still be settling: look it up again
        return out, load(out)

    def view_rect(self):
        """(x, y, width, height) of the 3D render window on the screen."""
        if self._view is None:
            self._view = ogre_windows(self._xenv())[0]
        return self._view

    def panels(self, img):
        """The pixels of each Image display's panel (every render window but the 3D view)."""
        return [crop(img, rect) for rect in ogre_windows(self._xenv())[1:]]

    def view(self, img):
        """The 3D view's pixels of a screenshot."""
        return crop(img, self.view_rect())

    def settle(self, predicate, timeout=30, interval=0.5, min_wait=2.0, out=None):
        """Screenshot until predicate(img) holds or `timeout` s pass.

        Returns (path, img) of the first shot that satisfies the predicate, else of the
        last one: callers then assert on it and name the file in their message.
        """
        time.sleep(min_wait)
        deadline = time.monotonic() + timeout
        while True:
            try:
                path, img = self.shot(out)
            except ScreenGrabError:
                # A failed grab is no picture, not a verdict: grab again until the deadline.
                if time.monotonic() > deadline:
                    raise
                time.sleep(interval)
                continue
            except RvizCrashed as crash:
                if self.pictures or self.crash_restarts <= 0:
                    raise
                self.crash_restarts -= 1
                print(f"rviz_screenshot: rviz crashed at start-up, starting it again: {crash}")
                self.close()
                self.start()
                time.sleep(min_wait)
                deadline = time.monotonic() + timeout
                continue
            try:
                if predicate(img):
                    return path, img
            except RvizError:
                pass  # the render window is not mapped yet
            if time.monotonic() > deadline:
                return path, img
            time.sleep(interval)


# An xwininfo tree line:  0x600004 (has no name): ()  900x709+16+0  +364+62
_WINDOW = re.compile(r"^\s+0x[0-9a-f]+ \(has no name\): \(\)\s+(\d+)x(\d+)\S*\s+\+(-?\d+)\+(-?\d+)")


def ogre_windows(xenv):
    """(x, y, width, height) of rviz's render windows, largest (the 3D view) first.

    Ogre draws the 3D view and each Image display into native X windows that have no
    name; Qt's own windows are all named after the application.
    """
    done = subprocess.run(
        ["xwininfo", "-root", "-tree"], env=xenv, capture_output=True, text=True, timeout=10
    )
    if done.returncode != 0:
        raise RvizError("xwininfo failed: " + done.stderr.strip())
    rects = parse_ogre_windows(done.stdout)
    if not rects:
        raise RvizError("no render window found in the X tree:\n" + done.stdout)
    return rects


def parse_ogre_windows(tree):
    """Unnamed windows larger than 50×50 px in `xwininfo -root -tree` output, largest first."""
    rects = []
    for line in tree.splitlines():
        match = _WINDOW.match(line)
        if match:
            w, h, x, y = (int(v) for v in match.groups())
            if w > 50 and h > 50:
                rects.append((x, y, w, h))
    return sorted(rects, key=lambda r: r[2] * r[3], reverse=True)


# -- pixel analysis ---------------------------------------------------------------------
def load(path):
    """PNG/PPM → H×W×3 uint8 array."""
    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"), dtype=np.uint8)


def crop(img, rect):
    x, y, w, h = rect
    return img[y : y + h, x : x + w]


def mask_rgb(img, rgb, tol=12):
    """Pixels within `tol` (per channel) of the colour `rgb`."""
    diff = np.abs(img.astype(np.int16) - np.array(rgb, dtype=np.int16))
    return diff.max(axis=2) <= tol


def count_rgb(img, rgb, tol=12):
    return int(np.count_nonzero(mask_rgb(img, rgb, tol)))


def hsv(img):
    """Hue (degrees; NaN for greys), saturation and value (0..1) arrays of an RGB image."""
    rgb = img.astype(np.float32) / 255.0
    mx = rgb.max(axis=2)
    mn = rgb.min(axis=2)
    span = mx - mn
    sat = np.where(mx > 0, span / np.maximum(mx, 1e-6), 0.0)
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    safe = np.maximum(span, 1e-6)
    hue = np.select(
        [mx == r, mx == g],
        [((g - b) / safe) % 6.0, (b - r) / safe + 2.0],
        (r - g) / safe + 4.0,
    )
    hue = np.where(span > 0, hue * 60.0, np.nan)  # greys have no hue: never in a hue range
    return hue, sat, mx


def mask_hsv(img, hue, sat=(0.0, 1.0), val=(0.0, 1.0), hsv_of_img=None):
    """Pixels whose hue lies in [lo, hi] degrees (wrapping if lo > hi), sat and value in range.

    Pass hsv_of_img (from hsv(img)) to reuse it across several masks of one picture.
    """
    h, s, v = hsv(img) if hsv_of_img is None else hsv_of_img
    lo, hi = hue
    in_hue = (h >= lo) & (h <= hi) if lo <= hi else (h >= lo) | (h <= hi)
    return in_hue & (s >= sat[0]) & (s <= sat[1]) & (v >= val[0]) & (v <= val[1])


def count_hsv(img, hue, sat=(0.0, 1.0), val=(0.0, 1.0)):
    return int(np.count_nonzero(mask_hsv(img, hue, sat, val)))


def centroid(mask):
    """(x, y) mean position of a mask's pixels, or None when it is empty."""
    ys, xs = np.nonzero(mask)
    if len(xs) == 0:
        return None
    return float(xs.mean()), float(ys.mean())


def extent(mask):
    """(width, height) of a mask's bounding box in pixels (0, 0 when empty)."""
    ys, xs = np.nonzero(mask)
    if len(xs) == 0:
        return 0, 0
    return int(xs.max() - xs.min() + 1), int(ys.max() - ys.min() + 1)


def is_blank(img, tol=6):
    """True when the picture is one flat colour (nothing drawn)."""
    return int(img.max()) - int(img.min()) <= tol


def screenshot(config, out, env=None, wait=8.0, workdir=None):
    """Start rviz, wait `wait` seconds, save one screenshot to `out`, stop rviz."""
    with RvizSession(config, env, workdir) as rviz:
        time.sleep(wait)
        path, _ = rviz.shot(out)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("config", help="rviz config (.rviz)")
    parser.add_argument("out", help="PNG to write")
    parser.add_argument("--wait", type=float, default=8.0, help="seconds before the shot")
    parser.add_argument("--master", help="ROS_MASTER_URI (default: the environment's)")
    args = parser.parse_args(argv)
    env = dict(os.environ)
    if args.master:
        env["ROS_MASTER_URI"] = args.master
    try:
        print(screenshot(args.config, args.out, env, args.wait))
    except (RvizError, FileNotFoundError) as err:
        print(f"rviz_screenshot: {err}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
