#pragma once
#include <cstddef>
#include <vector>

namespace vrrw_control
{
/// \brief Per-joint tolerances of a running goal; a value <= 0 is not checked.
struct Tolerances
{
  std::vector<double> path_position, path_velocity;
  std::vector<double> goal_position, goal_velocity;
  double goal_time = 0.0;  ///< s after the trajectory end by which the goal tolerances must hold

  static Tolerances uniform(size_t joints, double path_position, double goal_position, double goal_velocity,
                            double goal_time);
};
}  // namespace vrrw_control
