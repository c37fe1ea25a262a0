#pragma once
#include <ompl/base/MotionValidator.h>
#include <utility>

namespace vrrw_kinematics
{
class MotionPlanner;

/// \brief OMPL motion checks delegated to MotionPlanner::segmentValid (no link travels more than the
/// planner's resolution between two checked states).
class ResolutionMotionValidator : public ompl::base::MotionValidator
{
public:
  ResolutionMotionValidator(const ompl::base::SpaceInformationPtr& si, MotionPlanner& planner);

  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

private:
  MotionPlanner& planner_;
};
}  // namespace vrrw_kinematics
