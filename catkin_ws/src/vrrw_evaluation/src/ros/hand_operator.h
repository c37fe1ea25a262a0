#pragma once
// The scripted operator's hand: a tracked hand on /operator/<hand>/pose and /operator/<hand>/grip that grabs
// the robot's wrist while /<robot>/free_drive holds the arm compliant, the way a VR operator pulls the robot.
// In lockstep: it grabs and lets go while the simulation waits, and moves ahead of simulated time, its poses
// stamped with when they take effect.
#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <functional>
#include <mutex>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <string>
#include <utility>
#include <vector>
#include <vrrw_msgs/Event.h>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/ros/lockstep_client.h>

namespace vrrw_evaluation
{
class HandOperator
{
public:
  /// \brief `sim`: the hold on the physics node the pull is stepped through.
  HandOperator(ros::NodeHandle& node, const std::string& robot, vrrw_physics::LockstepClient& sim,
               const std::string& hand = "right");

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
  void publish(const Eigen::Isometry3d& pose, const ros::Time& stamp);
  void publish(double grip);
  /// Waits (wall clock, at most `seconds`) until `done()` holds (mutex_ held while it is asked).
  bool await(const std::function<bool()>& done, double seconds);
  /// While the simulation waits, once each: the open hand at `pose` stamped where it waits, until the interaction
  /// node passed it on to physics (queued there: /physics/input_queued); the grip closes, until the `grab` event
  /// (retried after opening: once the hand grabs nothing). The interaction node measures a hand's silence in ROS
  /// time, so a hand that holds still while the simulation waits needs no repeated poses: a lockstep teach sends
  /// the same messages each time.
  bool closeOn(const Eigen::Isometry3d& pose);
  /// The hand's grip set to `grip`, until this hand's /operator/events event of `kind` (at most 1 s, wall clock).
  bool gripUntil(double grip, const std::string& kind);
  /// The hand at `poses`, one every 10 ms of simulated time from where the simulation waits, a slice at a time:
  /// each slice is published stamped ahead of simulated time and stepped once physics has queued its spring
  /// targets (/physics/input_queued).
  bool pull(const std::vector<Eigen::Isometry3d>& poses, std::string& error);

  std::string robot_, hand_, pose_topic_, grip_topic_;
  vrrw_physics::LockstepClient& sim_;
  ros::Publisher pose_, grip_;
  std::vector<std::string> used_;
  vrrw_common::PersistentServices links_;
  std::mutex mutex_;                      ///< protects the two below
  std::vector<std::string> events_seen_;  ///< PROTECTED BY mutex_: kinds of this hand's /operator/events
  ros::Time spring_target_;  ///< PROTECTED BY mutex_: the latest spring target stamp physics has queued
  ros::Time hand_at_;        ///< PROTECTED BY mutex_: the latest stamp of this hand physics has queued
  ros::Subscriber events_, inputs_queued_;
};
}  // namespace vrrw_evaluation
