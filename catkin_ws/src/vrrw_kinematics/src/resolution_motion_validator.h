#pragma once
#include <ompl/base/MotionValidator.h>
#include <utility>

#include "vrrw_kinematics/segment_checker.h"

namespace vrrw_kinematics
{
/// \brief OMPL motion checks by the planner's SegmentChecker (no link travels more than the planner's
/// resolution between two checked states).
class ResolutionMotionValidator : public ompl::base::MotionValidator
{
public:
  ResolutionMotionValidator(const ompl::base::SpaceInformationPtr& si, SegmentChecker& segments);

  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

private:
  SegmentChecker& segments_;
  std::size_t dimension_;
};
}  // namespace vrrw_kinematics
