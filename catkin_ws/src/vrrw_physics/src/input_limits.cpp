#include <vrrw_physics/input_limits.h>

#include <cmath>
#include <sstream>

namespace vrrw_physics
{
void requireInRange(double value, double low, double high, const std::string& what, const std::string& unit)
{
  if (value >= low && value <= high)
    return;
  std::ostringstream text;
  text << what << ": " << value << " outside [" << low << ", " << high << "]" << (unit.empty() ? "" : " ") << unit;
  throw InputError(text.str());
}

void requireWorkspacePose(const Eigen::Isometry3d& pose, const std::string& what)
{
  if (!pose.matrix().allFinite())
    throw InputError(what + ": pose is not finite");
  const Eigen::Matrix3d r = pose.rotation();
  if (!(r.transpose() * r).isIdentity(1e-6) || !(r.determinant() > 0.0))
    throw InputError(what + ": orientation is not a rotation");
  const Eigen::Vector3d p = pose.translation();
  for (int i = 0; i < 3; ++i)
    requireInRange(p[i], -kWorldExtent, kWorldExtent, what + ": position." + "xyz"[i], "m (the world extent)");
}
}  // namespace vrrw_physics
