#pragma once
#include <Eigen/Dense>
#include <vector>
#include <vrrw_scene/scene.h>

#include "vrrw_kinematics/robot_model.h"

namespace vrrw_kinematics
{
/// \brief The model's variable vector with every robot at its scene initial positions (neutral elsewhere).
Eigen::VectorXd initialState(const RobotModel& model, const vrrw_scene::Scene& scene);

/// \brief The scene's acceleration limits of the robot's arm joints, base to tip; throws
/// KinematicsError(InvalidArgument) naming an arm joint without one.
std::vector<double> armAccelerationLimits(const vrrw_scene::Robot& robot);
}  // namespace vrrw_kinematics
