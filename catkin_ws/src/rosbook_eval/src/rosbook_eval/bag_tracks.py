"""Trajectories and the SLAM map from a bag (the I/O edge of the library: needs rosbag).

Odometry is read from /odom (nav_msgs/Odometry) for every entry point: the robot's own
report, stamped by the simulator; its odom → base_footprint transform on /tf carries the same
poses. SLAM's correction is the map → odom transform on /tf.
"""

import numpy as np
import rosbag
from rosbook_env.geometry import yaw_of

from rosbook_eval.poses import Trajectory, chain

TRUTH_TOPIC = "/base_pose_ground_truth"
ODOM_TOPIC = "/odom"


def _pose_of(pose):
    return (pose.position.x, pose.position.y, yaw_of(pose.orientation))


def read_tracks(
    bag_path,
    map_frame="map",
    odom_frame="odom",
    truth_topic=TRUTH_TOPIC,
    odom_topic=ODOM_TOPIC,
    need_correction=True,
):
    """Returns (ground truth, odometry, map→odom) trajectories from a recorded run. A topic
    given as None is not read (its trajectory is empty)."""
    stamps = {"truth": [], "odom": [], "correction": []}
    poses = {"truth": [], "odom": [], "correction": []}
    with rosbag.Bag(str(bag_path)) as bag:
        topics = [t for t in (truth_topic, odom_topic) if t] + ["/tf"]
        for topic, msg, _ in bag.read_messages(topics):
            if topic == "/tf":
                for tf in msg.transforms:
                    if tf.header.frame_id.lstrip("/") == map_frame and (
                        tf.child_frame_id.lstrip("/") == odom_frame
                    ):
                        t = tf.transform.translation
                        stamps["correction"].append(tf.header.stamp.to_sec())
                        poses["correction"].append((t.x, t.y, yaw_of(tf.transform.rotation)))
                continue
            key = "truth" if topic == truth_topic else "odom"
            stamps[key].append(msg.header.stamp.to_sec())
            poses[key].append(_pose_of(msg.pose.pose))
    tracks = {k: Trajectory(stamps[k], poses[k]) for k in stamps}
    for name, label in (("truth", truth_topic), ("odom", odom_topic)):
        if label and len(tracks[name]) < 2:
            raise ValueError(
                f"{bag_path}: fewer than two {label} messages; record them with the run"
            )
    if need_correction and not len(tracks["correction"]):
        raise ValueError(
            f"{bag_path}: no {map_frame}→{odom_frame} transforms on /tf; record /tf during a "
            "live SLAM run"
        )
    return tracks["truth"], tracks["odom"], tracks["correction"]


def read_correction(bag_path, map_frame="map", odom_frame="odom"):
    """SLAM's map→odom trajectory alone, from a bag of a live run (no truth needed)."""
    return read_tracks(bag_path, map_frame, odom_frame, truth_topic=None, odom_topic=None)[2]


def live_slam_track(correction, odom):
    """A live run's SLAM pose in the map frame: map→odom ∘ odometry at odometry's stamps."""
    return chain(correction, odom)


def read_last_map(bag_path, topic="/map"):
    """The last nav_msgs/OccupancyGrid on `topic` as a grid (cells, resolution, origin), or
    None when the bag holds none."""
    last = None
    with rosbag.Bag(str(bag_path)) as bag:
        for _, msg, _ in bag.read_messages([topic]):
            last = msg
    if last is None:
        return None
    info = last.info
    cells = np.array(last.data, dtype=np.int16).astype(np.int8).reshape(info.height, info.width)
    origin = (info.origin.position.x, info.origin.position.y, yaw_of(info.origin.orientation))
    # The message's resolution is a float32 (0.05 arrives as 0.0500000007); its shortest
    # decimal is what the map means and what map_saver writes, so a map read from the bag and
    # the same map saved to a file place their cells alike.
    return cells, float(str(np.float32(info.resolution))), origin
