#pragma once
#include <cstddef>
#include <vector>

namespace vrrw_control
{
/// \brief Positions, velocities and accelerations of a set of joints at one instant.
struct JointSample
{
  std::vector<double> positions;
  std::vector<double> velocities;
  std::vector<double> accelerations;

  JointSample() = default;
  explicit JointSample(size_t n) : positions(n, 0.0), velocities(n, 0.0), accelerations(n, 0.0) {}
  size_t size() const { return positions.size(); }
};
}  // namespace vrrw_control
