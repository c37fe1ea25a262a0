#include <vrrw_kinematics/joint_bounds.h>

#include <cmath>

namespace vrrw_kinematics
{
JointBounds::JointBounds(const RobotModel& model, const std::vector<std::string>& joints)
  : names_(joints), lower_(static_cast<Eigen::Index>(joints.size())), upper_(static_cast<Eigen::Index>(joints.size()))
{
  for (std::size_t i = 0; i < joints.size(); ++i)
  {
    const JointModel& joint = model.joints()[model.jointIndex(joints[i])];
    lower_[static_cast<Eigen::Index>(i)] = joint.lower;
    upper_[static_cast<Eigen::Index>(i)] = joint.upper;
    continuous_.push_back(joint.type == JointModel::Type::Continuous);
  }
}

std::string JointBounds::violation(const Eigen::VectorXd& q) const
{
  if (static_cast<std::size_t>(q.size()) != size())
    return "expected " + std::to_string(size()) + " joint values, got " + std::to_string(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i)
    if (!std::isfinite(q[i]) ||
        (!continuous_[static_cast<std::size_t>(i)] && (q[i] < lower_[i] - 1e-9 || q[i] > upper_[i] + 1e-9)))
      return "joint " + names_[static_cast<std::size_t>(i)] + " = " + std::to_string(q[i]) + " outside [" +
             std::to_string(lower_[i]) + ", " + std::to_string(upper_[i]) + "]";
  return "";
}

Eigen::VectorXd JointBounds::nearestTurn(const Eigen::VectorXd& q, const Eigen::VectorXd& reference) const
{
  Eigen::VectorXd out = q;
  for (Eigen::Index i = 0; i < q.size(); ++i)
    if (continuous_[static_cast<std::size_t>(i)])
    {
      const double delta = q[i] - reference[i];
      out[i] = reference[i] + delta - 2.0 * M_PI * std::nearbyint(delta / (2.0 * M_PI));
    }
  return out;
}
}  // namespace vrrw_kinematics
