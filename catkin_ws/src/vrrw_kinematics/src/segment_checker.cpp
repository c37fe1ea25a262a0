#include "vrrw_kinematics/segment_checker.h"

#include <algorithm>
#include <cmath>

namespace vrrw_kinematics
{
SegmentChecker::SegmentChecker(StateChecker& checker, double resolution)
  : checker_(checker), reach_(checker.reach()), resolution_(resolution)
{
}

std::size_t SegmentChecker::steps(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const
{
  double travel = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    travel += reach_[i] * std::abs(b[i] - a[i]);
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(travel / resolution_)));
}

bool SegmentChecker::valid(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double* valid_fraction)
{
  const std::size_t count = steps(a, b);
  const auto at = [&](std::size_t s) {
    return Eigen::VectorXd(a + (static_cast<double>(s) / static_cast<double>(count)) * (b - a));
  };
  if (valid_fraction)
  {
    for (std::size_t s = 1; s <= count; ++s)
      if (!checker_.valid(at(s)))
      {
        *valid_fraction = static_cast<double>(s - 1) / static_cast<double>(count);
        return false;
      }
    return true;
  }
  if (!checker_.valid(b))
    return false;
  std::size_t stride = 1;
  while (stride < count)
    stride *= 2;
  for (; stride >= 1; stride /= 2)
    for (std::size_t s = stride; s < count; s += 2 * stride)
      if (!checker_.valid(at(s)))
        return false;
  return true;
}
}  // namespace vrrw_kinematics
