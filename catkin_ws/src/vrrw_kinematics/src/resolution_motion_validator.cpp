#include "resolution_motion_validator.h"

#include <ompl/base/SpaceInformation.h>

#include "ompl_state.h"

namespace vrrw_kinematics
{
ResolutionMotionValidator::ResolutionMotionValidator(const ompl::base::SpaceInformationPtr& si,
                                                     SegmentChecker& segments)
  : ompl::base::MotionValidator(si), segments_(segments), dimension_(si->getStateDimension())
{
}

bool ResolutionMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const
{
  const bool ok = segments_.valid(toEigen(s1, dimension_), toEigen(s2, dimension_));
  (ok ? valid_ : invalid_)++;
  return ok;
}

bool ResolutionMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                                            std::pair<ompl::base::State*, double>& last_valid) const
{
  const Eigen::VectorXd a = toEigen(s1, dimension_), b = toEigen(s2, dimension_);
  double fraction = 1.0;
  const bool ok = segments_.valid(a, b, &fraction);
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
