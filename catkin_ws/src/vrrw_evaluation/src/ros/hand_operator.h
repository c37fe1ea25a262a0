#pragma once
// The scripted operator's hand: a tracked hand on /operator/<hand>/pose and /operator/<hand>/grip that grabs
// the robot's wrist while /<robot>/free_drive holds the arm compliant, the way a VR operator pulls the robot.
#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <mutex>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <string>
#include <utility>
#include <vector>
#include <vrrw_msgs/Event.h>

#include <vrrw_common/ros/persistent_service.h>

namespace vrrw_evaluation
{
class HandOperator
{
public:
  HandOperator(ros::NodeHandle& node, const std::string& robot, const std::string& hand = "right");

  /// \brief Waits for /<robot>/free_drive and for the interaction node to take the hand's topics.
  bool waitUntilReady(double seconds, std::string& error);

  /// \brief Free-drive on, the hand closes on the wrist at `grab` (world), carries it so that the TCP moves
  /// from `tcp_from` to `tcp_to` along a straight minimum-jerk line in `seconds`, holds still for `dwell` s,
  /// free-drive off (the arm holds where it is), the hand opens. false with `error` naming the step.
  bool freeDrive(const Eigen::Isometry3d& tcp_from, const Eigen::Isometry3d& tcp_to, const Eigen::Vector3d& grab,
                 double seconds, double dwell, std::string& error);

  /// \brief The interfaces used since the last take (metrics.json's teach.interfaces).
  std::vector<std::string> takeUsed() { return std::exchange(used_, {}); }

private:
  bool setFreeDrive(bool on, std::string& error);
  void publish(const Eigen::Isometry3d& pose, double grip);
  /// Publishes `pose` at 100 Hz with `grip` until an /operator/events event of `kind` for this hand or `seconds`.
  bool holdUntil(const Eigen::Isometry3d& pose, double grip, const std::string& kind, double seconds);

  std::string robot_, hand_, pose_topic_, grip_topic_;
  ros::Publisher pose_, grip_;
  ros::Subscriber events_;
  std::mutex mutex_;
  std::vector<std::string> events_seen_;  ///< kinds of this hand's /operator/events since the last drive
  std::vector<std::string> used_;
  vrrw_common::PersistentServices links_;
};
}  // namespace vrrw_evaluation
