#pragma once
#include <Eigen/Dense>

namespace vrrw_kinematics
{
/// \brief True when two world-frame axis-aligned boxes (centre, half extents) overlap or touch.
inline bool aabbOverlap(const Eigen::Vector3d& ca, const Eigen::Vector3d& ha, const Eigen::Vector3d& cb,
                        const Eigen::Vector3d& hb)
{
  return ((ca - cb).cwiseAbs() - ha - hb).maxCoeff() <= 0.0;
}
}  // namespace vrrw_kinematics
