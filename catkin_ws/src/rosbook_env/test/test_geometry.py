"""The shared quaternion <-> yaw helpers."""

import math
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from rosbook_env.geometry import quaternion_to_yaw, yaw_of, yaw_to_quaternion  # noqa: E402


@pytest.mark.parametrize("yaw", [0.0, 0.3, -1.2, math.pi / 2, 3.0, -3.0])
def test_yaw_quaternion_round_trip(yaw):
    assert quaternion_to_yaw(*yaw_to_quaternion(yaw)) == pytest.approx(yaw)


def test_yaw_of_a_message_and_of_a_dict():
    x, y, z, w = yaw_to_quaternion(0.7)
    assert yaw_of(SimpleNamespace(x=x, y=y, z=z, w=w)) == pytest.approx(0.7)
    assert yaw_of({"x": x, "y": y, "z": z, "w": w}) == pytest.approx(0.7)


def test_yaw_ignores_roll_and_pitch_of_a_level_turn():
    # A rotation by pi about x (an upside-down mount) then 0.5 about z: yaw is still 0.5.
    half = 0.25
    qz = (0.0, 0.0, math.sin(half), math.cos(half))
    qx = (1.0, 0.0, 0.0, 0.0)
    # qz * qx (Hamilton product)
    x = qz[3] * qx[0] + qz[0] * qx[3] + qz[1] * qx[2] - qz[2] * qx[1]
    y = qz[3] * qx[1] - qz[0] * qx[2] + qz[1] * qx[3] + qz[2] * qx[0]
    z = qz[3] * qx[2] + qz[0] * qx[1] - qz[1] * qx[0] + qz[2] * qx[3]
    w = qz[3] * qx[3] - qz[0] * qx[0] - qz[1] * qx[1] - qz[2] * qx[2]
    assert quaternion_to_yaw(x, y, z, w) == pytest.approx(0.5)
