#pragma once
#include <map>
#include <memory>
#include <ros/ros.h>
#include <vrrw_msgs/AttachObject.h>
#include <vrrw_msgs/CheckState.h>
#include <vrrw_msgs/ComputeFK.h>
#include <vrrw_msgs/ComputeIK.h>
#include <vrrw_msgs/Plan.h>

#include "scene_context.h"
#include "vrrw_kinematics/ik_solver.h"
#include "vrrw_kinematics/time_parameterization.h"

namespace vrrw_kinematics
{
/// \brief compute_fk, compute_ik, check_state, plan and attach_object for one robot, under /<robot>/.
class RobotServices
{
public:
  RobotServices(ros::NodeHandle& nh, const vrrw_scene::Robot& robot, SceneContext& context);

private:
  bool computeFk(vrrw_msgs::ComputeFK::Request& req, vrrw_msgs::ComputeFK::Response& res);
  bool computeIk(vrrw_msgs::ComputeIK::Request& req, vrrw_msgs::ComputeIK::Response& res);
  bool checkState(vrrw_msgs::CheckState::Request& req, vrrw_msgs::CheckState::Response& res);
  bool plan(vrrw_msgs::Plan::Request& req, vrrw_msgs::Plan::Response& res);
  bool attachObject(vrrw_msgs::AttachObject::Request& req, vrrw_msgs::AttachObject::Response& res);

  const IkSolver& solverFor(const std::string& link);
  Eigen::VectorXd armValues(const Eigen::VectorXd& state) const;
  void setArm(Eigen::VectorXd& state, const Eigen::VectorXd& arm) const;
  std::string linkOrTcp(const std::string& link) const;

  vrrw_scene::Robot robot_;
  SceneContext& context_;
  std::string arm_base_;
  std::vector<int> arm_variables_;
  std::map<std::string, std::unique_ptr<IkSolver>> solvers_;
  std::unique_ptr<TimeParameterization> timing_;          ///< blended corners
  std::unique_ptr<TimeParameterization> timing_exact_;    ///< stops at every waypoint, stays on the path
  std::vector<ros::ServiceServer> servers_;
};
}  // namespace vrrw_kinematics
