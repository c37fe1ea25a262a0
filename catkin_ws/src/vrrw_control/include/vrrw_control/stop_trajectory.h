#pragma once
#include <vector>
#include <vrrw_control/joint_sample.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_control
{
/// \brief A stop from a moving state with one constant deceleration per joint, all joints
/// coming to rest together, none decelerating faster than its bound: q(t) = q0 + v0 t - v0 t^2 / 2T.
/// Two points (current state, rest state) whose cubic interpolant is exactly that parabola.
vrrw_trajectory::JointTrajectory makeStopTrajectory(const std::vector<std::string>& joints, const JointSample& current,
                                                    const std::vector<double>& max_deceleration);
}  // namespace vrrw_control
