#include "resolution_motion_validator.h"

#include "ompl_state.h"
#include "vrrw_kinematics/motion_planner.h"

namespace vrrw_kinematics
{
ResolutionMotionValidator::ResolutionMotionValidator(const ompl::base::SpaceInformationPtr& si, MotionPlanner& planner)
  : ompl::base::MotionValidator(si), planner_(planner)
{
}

bool ResolutionMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const
{
  const std::size_t n = planner_.size();
  const bool ok = planner_.segmentValid(toEigen(s1, n), toEigen(s2, n));
  (ok ? valid_ : invalid_)++;
  return ok;
}

bool ResolutionMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                                            std::pair<ompl::base::State*, double>& last_valid) const
{
  const std::size_t n = planner_.size();
  const Eigen::VectorXd a = toEigen(s1, n), b = toEigen(s2, n);
  double fraction = 1.0;
  const bool ok = planner_.segmentValid(a, b, &fraction);
  if (!ok)
  {
    if (last_valid.first)
      fromEigen(a + fraction * (b - a), last_valid.first);
    last_valid.second = fraction;
  }
  (ok ? valid_ : invalid_)++;
  return ok;
}
}  // namespace vrrw_kinematics
