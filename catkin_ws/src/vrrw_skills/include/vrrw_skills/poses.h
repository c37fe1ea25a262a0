#pragma once
#include <vector>

#include <Eigen/Geometry>

#include <vrrw_dmp/cartesian_dmp.h>

namespace vrrw_skills
{
using vrrw_dmp::CartesianPose;

/// \brief The pose as a rigid transform, and back (the quaternion normalised, w >= 0).
Eigen::Isometry3d toIsometry(const CartesianPose& pose);
CartesianPose toPose(const Eigen::Isometry3d& transform);

/// \brief \a pose (world) expressed in \a frame (world): frame^-1 * pose.
CartesianPose relativeTo(const CartesianPose& frame, const CartesianPose& pose);
/// \brief \a relative (in \a frame) in the world: frame * relative.
CartesianPose inWorld(const CartesianPose& frame, const CartesianPose& relative);

/// \brief The mean position and the normalised mean quaternion (signs aligned with the first): the average of
/// close orientations (keyframes of several demonstrations).
CartesianPose averagePose(const std::vector<CartesianPose>& poses);

/// \brief Distance (m) and angle (rad) between two poses.
double positionDistance(const CartesianPose& a, const CartesianPose& b);
double angleDistance(const CartesianPose& a, const CartesianPose& b);
}  // namespace vrrw_skills
