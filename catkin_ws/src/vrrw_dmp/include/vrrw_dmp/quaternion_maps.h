#pragma once
#include <Eigen/Geometry>

namespace vrrw_dmp
{
/// \brief The logarithm of a unit quaternion q = (cos(a/2), sin(a/2) n): the vector (a/2) n, for the
/// rotation the shorter way round (q and -q are the same rotation: w < 0 is taken as -q). Twice it is the
/// rotation vector a n (Ude et al. 2014, eq. 17).
Eigen::Vector3d quaternionLog(const Eigen::Quaterniond& q);

/// \brief The exponential of a vector v = (a/2) n: the unit quaternion (cos |v|, sin |v| v / |v|), the
/// inverse of quaternionLog (Ude et al. 2014, eq. 16).
Eigen::Quaterniond quaternionExp(const Eigen::Vector3d& v);

/// \brief 2 log(a * conj(b)): the rotation vector (rad, world axes) that turns orientation b into a.
Eigen::Vector3d rotationBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// \brief The angle (rad, in [0, pi]) between two orientations.
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);
}  // namespace vrrw_dmp
