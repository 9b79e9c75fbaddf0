"""Trajectories from a bag: ground truth, odometry, and SLAM's map→odom correction."""

import rosbag

from rosbook_demo.trajectory import Trajectory, yaw_of


def _pose_of(pose):
    return (pose.position.x, pose.position.y, yaw_of(pose.orientation))


def read_tracks(bag_path, map_frame="map", odom_frame="odom"):
    """Returns (ground truth, odometry, map→odom) trajectories from a recorded run."""
    stamps = {"truth": [], "odom": [], "correction": []}
    poses = {"truth": [], "odom": [], "correction": []}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _ in bag.read_messages(["/base_pose_ground_truth", "/odom", "/tf"]):
            if topic == "/tf":
                for tf in msg.transforms:
                    if tf.header.frame_id.lstrip("/") == map_frame and (
                        tf.child_frame_id.lstrip("/") == odom_frame
                    ):
                        t = tf.transform.translation
                        stamps["correction"].append(tf.header.stamp.to_sec())
                        poses["correction"].append((t.x, t.y, yaw_of(tf.transform.rotation)))
                continue
            key = "truth" if topic == "/base_pose_ground_truth" else "odom"
            stamps[key].append(msg.header.stamp.to_sec())
            poses[key].append(_pose_of(msg.pose.pose))
    tracks = {k: Trajectory(stamps[k], poses[k]) for k in stamps}
    for name, label in (("truth", "/base_pose_ground_truth"), ("odom", "/odom")):
        if not len(tracks[name]):
            raise ValueError(f"{bag_path}: no {label} messages; record them with the run")
    if not len(tracks["correction"]):
        raise ValueError(f"{bag_path}: no {map_frame}→{odom_frame} transforms on /tf")
    return tracks["truth"], tracks["odom"], tracks["correction"]
