#pragma once
#include <vrrw_common/ros/action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <functional>
#include <optional>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <vrrw_msgs/GhostExecute.h>
#include <vrrw_msgs/GhostPlan.h>
#include <vrrw_msgs/GhostSetJoints.h>
#include <vrrw_msgs/GhostSetPose.h>

#include <vrrw_interaction/ghost_robot.h>
#include <vrrw_interaction/gripper.h>
#include <vrrw_interaction/plan_preview.h>

#include "arm_execution.h"
#include "send_schedule.h"
#include "world_view.h"

namespace vrrw_interaction
{
/// \brief One robot's ghost on ROS: /<robot>/ghost/joint_states, the ghost services, plan preview, execution
/// through the arm controller's action and the gripper's GripperCommand.
///
/// The ghost's joint_states go out at once on a request that moved it (services, menu, marker), and at the
/// instants of the live states (WorldView::onInstant) when it changed since (a plan's preview) or 1 s after the
/// last send (SendSchedule): no timer, so a lockstep simulation gets the same messages however fast it runs.
///
/// Every member below the services is PROTECTED BY the world's mutex (view.mutex()) unless it says otherwise;
/// the requests lock it themselves, the functions marked "(mutex held)" expect the caller to hold it.
class GhostInterface
{
public:
  /// \brief `execution_queue`: where ghost/execute is served. An execute waits for the whole motion, so it
  /// must not take one of the node's spinner threads (four in flight once left the node deaf: issue 21).
  GhostInterface(WorldView& view, const vrrw_scene::Robot& robot, const std::string& presets_file,
                 ros::CallbackQueue& execution_queue);

  const std::string& robot() const { return robot_; }
  std::vector<std::string> presetNames() const { return ghost_.presets().names(); }
  /// \brief The robot's arm (mutex held): free-drive solves the robot's own IK with it.
  vrrw_kinematics::Arm& arm() { return arm_; }
  /// \brief Called (mutex held) whenever the ghost moved by a service or the menu: the marker follows.
  std::function<void(const Eigen::Isometry3d& tcp)> on_moved;
  /// \brief Called (mutex held) after a request (service or menu, not a marker drag) published the moved ghost at
  /// `stamp`: the ghost frames follow at once.
  std::function<void(const ros::Time& stamp)> on_published;

  /// \brief Marker drag (mutex held): IK nearest the ghost, branch flips refused; publishes on success.
  Outcome drag(const Eigen::Isometry3d& target, const ros::Time& stamp, double max_jump);
  /// \brief Ghost TCP in the world (mutex held).
  Eigen::Isometry3d tcp() { return ghost_.tcpPose(view_.liveState()); }
  /// \brief Writes the ghost's arm into `state`, or the previewed plan's at `at` (ROS time) (mutex held).
  void ghostInto(Eigen::VectorXd& state, const ros::Time& at);

  // The requests behind the services and the marker's menu (each locks the mutex itself).
  Outcome preset(const std::string& name);
  Outcome addWaypoint();
  Outcome clearWaypoints();
  Outcome reset();
  Outcome plan(double time_limit, trajectory_msgs::JointTrajectory* trajectory = nullptr,
               const vrrw_kinematics::SpeedScaling& scaling = {},
               vrrw_kinematics::TimeProfile profile = vrrw_kinematics::TimeProfile::TimeOptimal);
  /// \brief Sends the last plan; with `result`, waits for the goal's own end (ArmExecution::run).
  Outcome execute(control_msgs::FollowJointTrajectoryResult* result = nullptr);
  Outcome gripper(bool close);
  /// \brief The scene object the held object may be set down on ("" = none); refused for an unknown one.
  Outcome supportSurface(const std::string& name);

private:
  void advertise(ros::NodeHandle& nh, ros::CallbackQueue& execution_queue);
  bool onSetJoints(vrrw_msgs::GhostSetJoints::Request& req, vrrw_msgs::GhostSetJoints::Response& res);
  bool onSetPose(vrrw_msgs::GhostSetPose::Request& req, vrrw_msgs::GhostSetPose::Response& res);
  bool onPlan(vrrw_msgs::GhostPlan::Request& req, vrrw_msgs::GhostPlan::Response& res);
  bool onExecute(vrrw_msgs::GhostExecute::Request& req, vrrw_msgs::GhostExecute::Response& res);
  /// \brief After a request that may have moved the ghost (mutex held): publish, tell the marker, log refusals.
  Outcome moved(const Outcome& outcome, const std::string& request);
  /// \brief At a live state's instant (mutex held): publishes the ghost if it changed or the keepalive is due.
  void atInstant(const ros::Time& stamp);
  /// \brief The ghost's arm joints (or the previewed plan's) at `at` (mutex held).
  Eigen::VectorXd joints(const ros::Time& at);
  /// \brief Publishes the ghost's joints `q` stamped `stamp`, sent at the instant `at` (mutex held).
  void publish(const Eigen::VectorXd& q, const ros::Time& stamp, const ros::Time& at);

  WorldView& view_;
  const std::string robot_;
  vrrw_kinematics::Arm arm_;
  GhostRobot ghost_;
  PlanPreview preview_;  ///< on ROS time: a plan previews at the pace the controller will run it
  Eigen::VectorXd sent_;  ///< the joints last published
  SendSchedule schedule_;
  const std::optional<GripperRange> gripper_;
  ros::Publisher joint_states_;  ///< (thread-safe by itself, as everything below)
  std::vector<ros::ServiceServer> services_;
  ArmExecution arm_action_;
  vrrw_common::ActionClient<control_msgs::GripperCommandAction> gripper_action_;
};
}  // namespace vrrw_interaction
