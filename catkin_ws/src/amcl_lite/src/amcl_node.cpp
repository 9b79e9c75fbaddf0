// amcl_lite's ROS node: amcl's topics, service, frames and parameters around the ROS-free
// particle filter. Subscribes scan, map (or calls static_map), initialpose; publishes
// amcl_pose, particlecloud and tf map -> odom; serves global_localization.
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <rosbook_env/master_watch.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Empty.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <utility>

#include "amcl_lite/particle_filter.h"

namespace amcl_lite {
namespace {

Pose2 toPose2(const geometry_msgs::Transform& t) {
  return Pose2(t.translation.x, t.translation.y, tf2::getYaw(t.rotation));
}

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

std::string stripSlash(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

class AmclNode {
 public:
  AmclNode() : pnh_("~"), listener_(buffer_) {
    readParameters();
    pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, true);
    cloud_pub_ = nh_.advertise<geometry_msgs::PoseArray>("particlecloud", 2, true);
    global_srv_ = nh_.advertiseService("global_localization", &AmclNode::onGlobalLocalization, this);
    initial_sub_ = nh_.subscribe("initialpose", 2, &AmclNode::onInitialPose, this);
    scan_sub_ = nh_.subscribe("scan", 5, &AmclNode::onScan, this);
    if (use_map_topic_) {
      map_sub_ = nh_.subscribe("map", 1, &AmclNode::onMap, this);
      ROS_INFO("amcl_lite: waiting for the map on topic %s", map_sub_.getTopic().c_str());
    } else {
      requestMap();
    }
  }

 private:
  // A private parameter, or `fallback` when it is not set. A value of the wrong type (a
  // string where a number belongs, 0.5 where a count belongs) is refused, not replaced by
  // the default without a word as NodeHandle::param would.
  template <typename T>
  T param(const std::string& name, T fallback) {
    if (!pnh_.hasParam(name)) return fallback;
    T value;
    if (!pnh_.getParam(name, value)) {
      XmlRpc::XmlRpcValue raw;
      pnh_.getParam(name, raw);
      std::ostringstream shown;
      shown << raw;
      throw std::invalid_argument("parameter " + name + " = " + shown.str() +
                                  " is invalid: it must be " + typeName(value));
    }
    return value;
  }
  static const char* typeName(double) { return "a number"; }
  static const char* typeName(int) { return "a whole number"; }
  static const char* typeName(bool) { return "true or false"; }
  static const char* typeName(const std::string&) { return "a string"; }

  void readParameters() {
    p_.min_particles = param("min_particles", p_.min_particles);
    p_.max_particles = param("max_particles", p_.max_particles);
    p_.kld_err = param("kld_err", p_.kld_err);
    p_.kld_z = param("kld_z", p_.kld_z);
    p_.odom_alpha1 = param("odom_alpha1", p_.odom_alpha1);
    p_.odom_alpha2 = param("odom_alpha2", p_.odom_alpha2);
    p_.odom_alpha3 = param("odom_alpha3", p_.odom_alpha3);
    p_.odom_alpha4 = param("odom_alpha4", p_.odom_alpha4);
    p_.laser_max_beams = param("laser_max_beams", p_.laser_max_beams);
    p_.laser_z_hit = param("laser_z_hit", p_.laser_z_hit);
    p_.laser_z_rand = param("laser_z_rand", p_.laser_z_rand);
    p_.laser_sigma_hit = param("laser_sigma_hit", p_.laser_sigma_hit);
    p_.laser_likelihood_max_dist = param("laser_likelihood_max_dist", p_.laser_likelihood_max_dist);
    p_.update_min_d = param("update_min_d", p_.update_min_d);
    p_.update_min_a = param("update_min_a", p_.update_min_a);
    p_.resample_interval = param("resample_interval", p_.resample_interval);
    p_.recovery_alpha_slow = param("recovery_alpha_slow", p_.recovery_alpha_slow);
    p_.recovery_alpha_fast = param("recovery_alpha_fast", p_.recovery_alpha_fast);
    p_.initial_pose_x = param("initial_pose_x", p_.initial_pose_x);
    p_.initial_pose_y = param("initial_pose_y", p_.initial_pose_y);
    p_.initial_pose_a = param("initial_pose_a", p_.initial_pose_a);
    p_.initial_cov_xx = param("initial_cov_xx", p_.initial_cov_xx);
    p_.initial_cov_yy = param("initial_cov_yy", p_.initial_cov_yy);
    p_.initial_cov_aa = param("initial_cov_aa", p_.initial_cov_aa);
    p_.transform_tolerance = param("transform_tolerance", p_.transform_tolerance);
    const std::string error = validate(p_);
    if (!error.empty()) throw std::invalid_argument(error);
    const std::string odom_model = param<std::string>("odom_model_type", "diff");
    if (odom_model != "diff")
      throw std::invalid_argument("parameter odom_model_type = '" + odom_model +
                                  "' is not supported: amcl_lite implements 'diff' only");
    const std::string laser_model = param<std::string>("laser_model_type", "likelihood_field");
    if (laser_model != "likelihood_field")
      throw std::invalid_argument("parameter laser_model_type = '" + laser_model +
                                  "' is not supported: amcl_lite implements 'likelihood_field' only");
    base_frame_ = stripSlash(param<std::string>("base_frame_id", "base_footprint"));
    odom_frame_ = stripSlash(param<std::string>("odom_frame_id", "odom"));
    global_frame_ = stripSlash(param<std::string>("global_frame_id", "map"));
    const std::pair<const char*, const std::string*> frames[] = {
        {"base_frame_id", &base_frame_}, {"odom_frame_id", &odom_frame_}, {"global_frame_id", &global_frame_}};
    for (const auto& [name, frame] : frames)
      if (frame->empty())
        throw std::invalid_argument(std::string("parameter ") + name +
                                    " is empty: it must name a TF frame (set it with _" + name + ":=FRAME)");
    transform_tolerance_ = ros::Duration(p_.transform_tolerance);
    use_map_topic_ = param("use_map_topic", false);
    tf_broadcast_ = param("tf_broadcast", true);
    seed_ = static_cast<uint32_t>(param("seed", 0));
  }

  void requestMap() {
    nav_msgs::GetMap srv;
    ROS_INFO("amcl_lite: requesting the map from service static_map");
    while (ros::ok() && !ros::service::call("static_map", srv)) {
      ROS_WARN_THROTTLE(5.0, "amcl_lite: service static_map not available yet (set ~use_map_topic "
                             "true to read the map topic instead)");
      ros::Duration(0.5).sleep();
    }
    if (ros::ok()) onMap(boost::make_shared<nav_msgs::OccupancyGrid>(srv.response.map));
  }

  void onMap(const nav_msgs::OccupancyGridConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    GridMap map;
    map.resolution = msg->info.resolution;
    map.origin_x = msg->info.origin.position.x;
    map.origin_y = msg->info.origin.position.y;
    map.width = static_cast<int>(msg->info.width);
    map.height = static_cast<int>(msg->info.height);
    map.cells = msg->data;
    try {
      field_ = std::make_shared<LikelihoodField>(map, p_.laser_likelihood_max_dist);
    } catch (const std::exception& e) {
      ROS_ERROR("amcl_lite: map refused: %s", e.what());
      return;
    }
    // A new map restarts the filter at the last estimate if there is one (amcl keeps its
    // pose across map updates), else at the initial_pose parameters.
    AmclParams start = p_;
    if (filter_) {
      const PoseEstimate e = filter_->estimate();
      start.initial_pose_x = e.mean.x;
      start.initial_pose_y = e.mean.y;
      start.initial_pose_a = e.mean.theta;
    }
    filter_ = std::make_unique<ParticleFilter>(start, field_, seed_);
    map_extent_ = map;
    map_extent_.cells.clear();  // the bounds are all onInitialPose needs
    const std::string problem =
        initialPoseProblem(map, start.initial_pose_x, start.initial_pose_y, start.initial_cov_xx, start.initial_cov_yy);
    if (!problem.empty()) {
      ROS_ERROR("amcl_lite: %s; spreading the particles over the map's free space "
                "instead (global localization). Set ~initial_pose_x/y and ~initial_cov_xx/yy, or use "
                "rviz's 2D Pose Estimate",
                problem.c_str());
      filter_->initGlobal();
    }
    last_odom_.reset();
    force_update_ = true;
    ROS_INFO("amcl_lite: map %dx%d at %.3f m, %zu particles around (%.2f, %.2f, %.2f)", map.width,
             map.height, map.resolution, filter_->particles().size(), start.initial_pose_x,
             start.initial_pose_y, start.initial_pose_a);
  }

  void onInitialPose(const geometry_msgs::PoseWithCovarianceStampedConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string frame = stripSlash(msg->header.frame_id);
    if (!frame.empty() && frame != global_frame_) {
      ROS_WARN("amcl_lite: ignoring initial pose in frame '%s'; it must be in '%s'", frame.c_str(),
               global_frame_.c_str());
      return;
    }
    if (!filter_) {
      ROS_WARN("amcl_lite: initial pose received before the map; ignoring it");
      return;
    }
    const auto& c = msg->pose.covariance;
    const Pose2 pose(msg->pose.pose.position.x, msg->pose.pose.position.y,
                     tf2::getYaw(msg->pose.pose.orientation));
    const bool finite_pose = std::isfinite(pose.x) && std::isfinite(pose.y) &&
                             std::isfinite(pose.theta);
    const bool usable_cov = std::isfinite(c[0]) && std::isfinite(c[7]) && std::isfinite(c[35]) &&
                            std::isfinite(c[1]) && c[0] >= 0 && c[7] >= 0 && c[35] >= 0;
    if (!finite_pose || !usable_cov) {
      ROS_WARN("amcl_lite: ignoring an initial pose that is not finite or whose covariance is "
               "negative or not finite: (%g, %g, %g), variances %g %g %g",
               pose.x, pose.y, pose.theta, c[0], c[7], c[35]);
      return;
    }
    const std::string problem = initialPoseProblem(map_extent_, pose.x, pose.y, c[0], c[7]);
    if (!problem.empty()) {
      ROS_WARN("amcl_lite: ignoring an initial pose: %s; to spread the particles over the whole map, "
               "call `rosservice call /global_localization`",
               problem.c_str());
      return;
    }
    filter_->initGaussian(pose, c[0], c[7], c[35], c[1]);
    force_update_ = true;
    ROS_INFO("amcl_lite: initial pose (%.3f, %.3f, %.3f)", pose.x, pose.y, pose.theta);
  }

  bool onGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!filter_) return false;
    filter_->initGlobal();
    force_update_ = true;
    ROS_INFO("amcl_lite: global localization: %zu particles spread over the free map",
             filter_->particles().size());
    return true;
  }

  bool lookup(const std::string& target, const std::string& source, const ros::Time& stamp,
              Pose2* out) {
    try {
      *out = toPose2(buffer_.lookupTransform(target, source, stamp, ros::Duration(0.5)).transform);
      return true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "amcl_lite: no transform %s -> %s at the scan's time: %s",
                        target.c_str(), source.c_str(), e.what());
      return false;
    }
  }

  void onScan(const sensor_msgs::LaserScanConstPtr& scan) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!filter_) return;
    Pose2 odom_base, laser_in_base;
    if (!lookup(odom_frame_, base_frame_, scan->header.stamp, &odom_base)) return;
    if (!lookup(base_frame_, stripSlash(scan->header.frame_id), ros::Time(0), &laser_in_base)) return;
    bool update = force_update_ || !last_odom_;
    if (last_odom_) {
      const Pose2 step = last_odom_->inverse() * odom_base;
      update = update || std::hypot(step.x, step.y) >= p_.update_min_d ||
               std::fabs(step.theta) >= p_.update_min_a;
    }
    if (update) {
      if (last_odom_) filter_->predict(*last_odom_, odom_base);
      last_odom_ = odom_base;
      force_update_ = false;
      ScanObservation obs;
      obs.range_min = scan->range_min;
      obs.range_max = scan->range_max;
      obs.laser_in_base = laser_in_base;
      for (int i : ParticleFilter::beamIndices(static_cast<int>(scan->ranges.size()), p_.laser_max_beams))
        obs.beams.push_back({scan->ranges[i], scan->angle_min + i * scan->angle_increment});
      filter_->correct(obs);
      const PoseEstimate e = filter_->estimate();
      map_odom_ = e.mean * odom_base.inverse();
      publishPose(e, scan->header.stamp);
      publishCloud(scan->header.stamp);
    }
    if (map_odom_ && tf_broadcast_) {
      // Dated transform_tolerance ahead, as amcl does: the map -> odom correction stays
      // usable until the next scan arrives.
      geometry_msgs::TransformStamped t;
      t.header.stamp = scan->header.stamp + transform_tolerance_;
      t.header.frame_id = global_frame_;
      t.child_frame_id = odom_frame_;
      t.transform.translation.x = map_odom_->x;
      t.transform.translation.y = map_odom_->y;
      t.transform.rotation = yawQuaternion(map_odom_->theta);
      broadcaster_.sendTransform(t);
    }
  }

  void publishPose(const PoseEstimate& e, const ros::Time& stamp) {
    geometry_msgs::PoseWithCovarianceStamped msg;
    msg.header.stamp = stamp;
    msg.header.frame_id = global_frame_;
    msg.pose.pose.position.x = e.mean.x;
    msg.pose.pose.position.y = e.mean.y;
    msg.pose.pose.orientation = yawQuaternion(e.mean.theta);
    msg.pose.covariance[0] = e.covariance[0];
    msg.pose.covariance[1] = e.covariance[1];
    msg.pose.covariance[6] = e.covariance[3];
    msg.pose.covariance[7] = e.covariance[4];
    msg.pose.covariance[35] = e.covariance[8];
    pose_pub_.publish(msg);
  }

  void publishCloud(const ros::Time& stamp) {
    geometry_msgs::PoseArray msg;
    msg.header.stamp = stamp;
    msg.header.frame_id = global_frame_;
    for (const Particle& p : filter_->particles()) {
      geometry_msgs::Pose pose;
      pose.position.x = p.pose.x;
      pose.position.y = p.pose.y;
      pose.orientation = yawQuaternion(p.pose.theta);
      msg.poses.push_back(pose);
    }
    cloud_pub_.publish(msg);
  }

  ros::NodeHandle nh_, pnh_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  tf2_ros::TransformBroadcaster broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_;
  ros::Subscriber scan_sub_, map_sub_, initial_sub_;
  ros::ServiceServer global_srv_;
  std::mutex mutex_;

  AmclParams p_;
  std::string base_frame_, odom_frame_, global_frame_;
  ros::Duration transform_tolerance_;
  bool use_map_topic_ = false, tf_broadcast_ = true, force_update_ = true;
  uint32_t seed_ = 0;
  std::shared_ptr<const LikelihoodField> field_;
  GridMap map_extent_;  // the current map's bounds (no cells), for checking initial poses
  std::unique_ptr<ParticleFilter> filter_;
  std::optional<Pose2> last_odom_, map_odom_;
};

}  // namespace
}  // namespace amcl_lite

int main(int argc, char** argv) {
  ros::init(argc, argv, "amcl");
  // Holds ROS up while the node is built: when the node's own handles are destroyed by a
  // refused parameter, ros::shutdown would otherwise silence rosconsole before ROS_FATAL.
  ros::NodeHandle keep_ros_up;
  try {
    amcl_lite::AmclNode node;
    const rosbook_env::MasterWatch master_watch;  // re-registers with a restarted roscore
    ros::spin();
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("amcl_lite: %s", e.what());
    return 2;
  }
  return 0;
}
