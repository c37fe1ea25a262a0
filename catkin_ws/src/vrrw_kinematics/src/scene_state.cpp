#include "vrrw_kinematics/scene_state.h"

#include "vrrw_kinematics/kinematics_error.h"

namespace vrrw_kinematics
{
Eigen::VectorXd initialState(const RobotModel& model, const vrrw_scene::Scene& scene)
{
  Eigen::VectorXd q = model.neutralState();
  for (const vrrw_scene::Robot& robot : scene.robots)
    for (const auto& entry : robot.initial_positions)
    {
      int v = model.variableIndex(entry.first);
      if (v < 0)
        v = model.variableIndex(robot.name + "_" + entry.first);
      if (v >= 0)
        q[v] = entry.second;
    }
  return q;
}

std::vector<double> armAccelerationLimits(const vrrw_scene::Robot& robot)
{
  std::vector<double> limits;
  for (const std::string& joint : robot.arm_joints)
  {
    const auto limit = robot.acceleration_limits.find(joint);
    if (limit == robot.acceleration_limits.end())
      throw KinematicsError(ErrorCode::InvalidArgument,
                            "robot " + robot.name + ": joint " + joint + ": no acceleration limit in the scene");
    limits.push_back(limit->second);
  }
  return limits;
}
}  // namespace vrrw_kinematics
