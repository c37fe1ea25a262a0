#pragma once
#include <ros/ros.h>
#include <vrrw_kinematics/arm.h>
#include <vrrw_msgs/AttachObject.h>
#include <vrrw_msgs/CheckPath.h>
#include <vrrw_msgs/CheckState.h>
#include <vrrw_msgs/ComputeFK.h>
#include <vrrw_msgs/ComputeIK.h>
#include <vrrw_msgs/Plan.h>

#include "scene_context.h"

namespace vrrw_kinematics
{
/// \brief compute_fk, compute_ik, check_state, check_path, plan and attach_object for one robot, under /<robot>/.
class RobotServices
{
public:
  /// \brief `stale_after` (s): answers taken from a live state older than this carry a warning.
  RobotServices(ros::NodeHandle& nh, const vrrw_scene::Robot& robot, SceneContext& context, double stale_after);

private:
  bool computeFk(vrrw_msgs::ComputeFK::Request& req, vrrw_msgs::ComputeFK::Response& res);
  bool computeIk(vrrw_msgs::ComputeIK::Request& req, vrrw_msgs::ComputeIK::Response& res);
  bool checkState(vrrw_msgs::CheckState::Request& req, vrrw_msgs::CheckState::Response& res);
  bool checkPath(vrrw_msgs::CheckPath::Request& req, vrrw_msgs::CheckPath::Response& res);
  bool plan(vrrw_msgs::Plan::Request& req, vrrw_msgs::Plan::Response& res);
  bool attachObject(vrrw_msgs::AttachObject::Request& req, vrrw_msgs::AttachObject::Response& res);

  /// \brief The plan request's goal, planner, time limit and seed; throws KinematicsError naming the field.
  PlanRequest planRequest(const vrrw_msgs::Plan::Request& req, const Eigen::VectorXd& state) const;
  /// \brief The arm joint values of a joint goal; throws KinematicsError naming a bad or repeated joint.
  Eigen::VectorXd goalJoints(const sensor_msgs::JointState& goal, const Eigen::VectorXd& start) const;
  /// \brief "" unless the arm's values come from a live state older than stale_after: then a warning
  /// naming its age, for the answer's message.
  std::string staleWarning(const sensor_msgs::JointState& given) const;
  std::string linkOrTcp(const std::string& link) const;

  Arm arm_;
  SceneContext& context_;
  double stale_after_;
  std::vector<ros::ServiceServer> servers_;
};
}  // namespace vrrw_kinematics
