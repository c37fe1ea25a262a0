#pragma once
// A scripted hand drags the free-driven UR5e's wrist through the interaction node's public interfaces:
// shared by the physics rostest and ./vrrw bench interaction.
#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <mutex>
#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <sstream>
#include <std_msgs/Float64.h>
#include <std_srvs/SetBool.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_msgs/Event.h>

namespace vrrw_interaction_bench
{
struct DragFigures
{
  std::string error;           ///< "" when the drag ran
  std::string body;            ///< what the hand took
  double rms = 0.0, max = 0.0;  ///< m, grabbed point vs hand target while moving
  /// deg, the grabbed link's orientation vs its orientation at the grab turned as the hand turned, while moving
  double angle_rms = 0.0, angle_max = 0.0;
  double drift = 0.0;          ///< m of the grabbed point over `hold` s after release with rigid drives
  int samples = 0;
};

/// \brief Free-drive on, a hand closes on the wrist, moves `distance` m along +y at `speed` m/s, opens;
/// free-drive off; the grabbed point is watched for `hold` s. With `turn` (rad) the hand also turns that much
/// about the world z axis (through itself) while it moves.
inline DragFigures dragWrist(ros::NodeHandle& nh, tf2_ros::Buffer& tf, double distance, double speed, double hold,
                             double turn = 0.0)
{
  DragFigures out;
  std::mutex mutex;
  std::vector<vrrw_msgs::Event> events;
  ros::Subscriber sub = nh.subscribe<vrrw_msgs::Event>("/operator/events", 100, [&](const vrrw_msgs::EventConstPtr& e) {
    std::lock_guard<std::mutex> lock(mutex);
    events.push_back(*e);
  });
  ros::Publisher pose_pub = nh.advertise<geometry_msgs::PoseStamped>("/operator/bench_hand/pose", 10);
  ros::Publisher grip_pub = nh.advertise<std_msgs::Float64>("/operator/bench_hand/grip", 10);
  const auto freeDrive = [&](bool on) {
    std_srvs::SetBool srv;
    srv.request.data = on;
    return ros::service::waitForService("/ur5e/free_drive", ros::Duration(30.0)) &&
           vrrw_common::services().tryCall("/ur5e/free_drive", srv) && srv.response.success;
  };
  const auto linkPose = [&](const std::string& link) {
    return tf2::transformToEigen(tf.lookupTransform("world", link, ros::Time(0), ros::Duration(2.0)));
  };
  if (!freeDrive(true))
    return out.error = "free_drive on failed", out;
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  hand.translation() = linkPose("ur5e_wrist_3_link").translation();
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "world";
  const auto send = [&] {
    pose.header.stamp = ros::Time::now();
    pose.pose = tf2::toMsg(hand);
    pose_pub.publish(pose);
  };
  for (int i = 0; i < 300 && grip_pub.getNumSubscribers() == 0; ++i, ros::WallDuration(0.01).sleep())
    send();
  for (int i = 0; i < 20; ++i, ros::WallDuration(0.01).sleep())
    send();  // the pose subscription may connect just after the grip's
  std_msgs::Float64 grip;
  grip.data = 1.0;
  grip_pub.publish(grip);
  Eigen::Vector3d grabbed_world;
  for (int i = 0; i < 100 && out.body.empty(); ++i, ros::WallDuration(0.01).sleep())
  {
    send();
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& e : events)
      if (e.kind == "grab")
      {
        std::istringstream detail(e.detail);  // "hand bench_hand grabbed LINK at (x, y, z)"
        std::string word, link;
        char c;
        detail >> word >> word >> word >> link >> word >> c >> grabbed_world.x() >> c >> grabbed_world.y() >> c >>
            grabbed_world.z();
        out.body = link;
      }
  }
  if (out.body.empty())
    return out.error = "no grab event", out;
  const Eigen::Isometry3d link_at_grab = linkPose(out.body);
  const Eigen::Vector3d point = link_at_grab.inverse() * grabbed_world;
  const Eigen::Vector3d start = hand.translation();
  const int steps = static_cast<int>(distance / speed * 100.0);
  double sum = 0.0, angle_sum = 0.0;
  ros::WallTime tick = ros::WallTime::now();
  for (int i = 1; i <= steps + 50; ++i)  // 100 Hz; then half a second at the end point
  {
    const Eigen::AngleAxisd turned(turn * std::min(1.0, double(i) / steps), Eigen::Vector3d::UnitZ());
    hand.translation() = start + Eigen::Vector3d(0, distance * std::min(1.0, double(i) / steps), 0);
    hand.linear() = turned.toRotationMatrix();
    send();
    tick += ros::WallDuration(0.01);
    if (const ros::WallDuration rest = tick - ros::WallTime::now(); rest > ros::WallDuration(0))
      rest.sleep();  // a negative WallDuration would sleep for ever
    if (i > steps)
      continue;
    const Eigen::Isometry3d link = linkPose(out.body);
    const Eigen::Vector3d target = start + turned * (grabbed_world - start) + (hand.translation() - start);
    const double error = (link * point - target).norm();
    const double angle =
        Eigen::AngleAxisd(link.rotation() * (turned * link_at_grab.rotation()).transpose()).angle() * 180.0 / M_PI;
    sum += error * error, out.max = std::max(out.max, error), ++out.samples;
    angle_sum += angle * angle, out.angle_max = std::max(out.angle_max, angle);
  }
  out.rms = std::sqrt(sum / out.samples);
  out.angle_rms = std::sqrt(angle_sum / out.samples);
  grip.data = 0.0;
  grip_pub.publish(grip);
  ros::WallDuration(0.1).sleep();
  if (!freeDrive(false))
    return out.error = "free_drive off failed", out;
  ros::WallDuration(0.2).sleep();
  const Eigen::Vector3d before = linkPose(out.body) * point;
  ros::WallDuration(hold).sleep();
  out.drift = (linkPose(out.body) * point - before).norm();
  return out;
}
}  // namespace vrrw_interaction_bench
