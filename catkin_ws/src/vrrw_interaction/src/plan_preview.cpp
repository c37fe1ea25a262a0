#include <vrrw_interaction/plan_preview.h>

namespace vrrw_interaction
{
void PlanPreview::play(const vrrw_trajectory::JointTrajectory& plan, double start)
{
  interpolator_.emplace(plan);
  start_ = start - plan.points.front().time;
}

std::optional<Eigen::VectorXd> PlanPreview::at(double now) const
{
  if (!interpolator_ || now - start_ > interpolator_->endTime() + kHold)
    return std::nullopt;
  const std::vector<double> q = interpolator_->sample(now - start_).positions;
  return Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size()));
}
}  // namespace vrrw_interaction
