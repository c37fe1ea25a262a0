#pragma once
#include <Eigen/Geometry>

namespace vrrw_kinematics
{
/// \brief A TCP pose (world) that takes `object` (its world pose) from above at `point` (in the object's
/// frame): the tool's z axis points straight down and its y axis, the fingers' closing direction, lies
/// along the object's y axis turned horizontal, so the fingers close across the object whatever its yaw.
Eigen::Isometry3d topGrasp(const Eigen::Isometry3d& object, const Eigen::Vector3d& point);
}  // namespace vrrw_kinematics
