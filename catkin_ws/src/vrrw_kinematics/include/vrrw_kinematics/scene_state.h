#pragma once
#include <Eigen/Dense>
#include <vrrw_scene/scene.h>

#include "vrrw_kinematics/robot_model.h"

namespace vrrw_kinematics
{
/// \brief The model's variable vector with every robot at its scene initial positions (neutral elsewhere).
Eigen::VectorXd initialState(const RobotModel& model, const vrrw_scene::Scene& scene);
}  // namespace vrrw_kinematics
