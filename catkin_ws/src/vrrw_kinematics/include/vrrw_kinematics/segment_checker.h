#pragma once
#include <Eigen/Dense>
#include <cstddef>
#include <vector>

#include "vrrw_kinematics/state_checker.h"

namespace vrrw_kinematics
{
/// \brief Checks straight joint-space segments of one group in steps small enough that no point of a
/// moving body travels more than `resolution` (m) between two checked states (StateChecker::reach()).
/// Between two checked states a motion is not checked: every point then lies within half a step of where
/// it was at a checked, collision-free state, so an accepted motion may graze something: half the
/// resolution deep past a face, up to the resolution at an edge (penetration depth), twice that between
/// two links of the group, which both move.
/// Shared by the planner's own path checks and OMPL's motion validator.
class SegmentChecker
{
public:
  SegmentChecker(StateChecker& checker, double resolution);

  double resolution() const { return resolution_; }
  /// \brief Number of steps the straight segment a-b is checked in.
  std::size_t steps(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  /// \brief Checks every step of the straight segment a-b (b included, a not). With `valid_fraction`, walks
  /// from a and gives the fraction known valid when it fails; without, checks b and then bisects, which
  /// finds a collision in the middle of a long segment sooner.
  bool valid(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double* valid_fraction = nullptr);

private:
  StateChecker& checker_;
  std::vector<double> reach_;
  double resolution_;
};
}  // namespace vrrw_kinematics
