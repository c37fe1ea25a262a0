#pragma once
// The scripted operator's ghost-drive: the same services an operator's marker menu calls
// (/<robot>/ghost/{reset,clear_waypoints,set_support_surface,set_pose,add_waypoint,plan,execute}), never a
// joint command.
#include <Eigen/Geometry>
#include <actionlib_msgs/GoalStatusArray.h>
#include <mutex>
#include <ros/ros.h>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/ros/lockstep_client.h>

namespace vrrw_evaluation
{
/// \brief How a ghost-drive is planned: MoveIt's speed sliders (0: full speed), the time profile ("":
/// time-optimal, "minimum_jerk") and, for a place, the scene object the held object is set down on (it may
/// touch it at the goal and on the last leg).
struct DriveOptions
{
  double velocity_scaling = 0.0;
  double acceleration_scaling = 0.0;
  std::string time_profile;
  std::string support_surface;
};

class GhostOperator
{
public:
  /// \brief `sim`: the hold on the physics node that the motions of ghost/execute are stepped through.
  GhostOperator(ros::NodeHandle& node, const std::string& robot, vrrw_physics::LockstepClient& sim);

  /// \brief Waits for the interaction node's ghost services; false with `error` naming the missing one.
  bool waitUntilReady(double seconds, std::string& error);

  /// \brief Ghost-drive: ghost = robot, its support surface set (options), the ghost at every TCP pose of
  /// `waypoints` (in "world") added as a waypoint, the ghost at `goal`, plan, execute. Adds the planning time
  /// to `plan_ms`. The simulation waits for every call but the execute, which it steps until the motion ended.
  bool drive(const std::vector<Eigen::Isometry3d>& waypoints, const Eigen::Isometry3d& goal, std::string& error,
             double* plan_ms = nullptr, const DriveOptions& options = {});

  /// \brief The services called since the last take, in first-call order (metrics.json's teach.interfaces).
  std::vector<std::string> takeUsed() { return std::exchange(used_, {}); }

private:
  bool trigger(const std::string& service, std::string& error);
  bool setPose(const Eigen::Isometry3d& tcp, std::string& error);
  /// ghost/execute, which answers once its motion ended: called on a thread of its own while this one steps the
  /// simulation, from when its goal is in the arm controller until every controller is idle.
  bool execute(std::string& error);
  void use(const std::string& service);

  std::string prefix_;  ///< /<robot>/ghost/
  std::string self_;    ///< "<this node>-": how actionlib's goal ids of this process begin
  vrrw_physics::LockstepClient& sim_;
  vrrw_common::PersistentServices links_;
  std::vector<std::string> used_;
  std::mutex mutex_;                 ///< protects goals_
  std::set<std::string> goals_;      ///< PROTECTED BY mutex_: ids of the arm controller's goals, active or done
  ros::Subscriber status_;           ///< the arm action's status: goals_
};
}  // namespace vrrw_evaluation
