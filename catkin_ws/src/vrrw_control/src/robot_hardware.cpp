#include <algorithm>
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
RobotHardware::RobotHardware(std::vector<std::string> joints)
  : joints_(std::move(joints))
  , state_(joints_.size())
  , command_(joints_.size())
  , efforts_(joints_.size(), 0.0)
  , effort_limits_(joints_.size(), 0.0)
{
}

int RobotHardware::index(const std::string& joint) const
{
  const auto it = std::find(joints_.begin(), joints_.end(), joint);
  return it == joints_.end() ? -1 : static_cast<int>(it - joints_.begin());
}

void RobotHardware::reset(const std::vector<double>& positions)
{
  state_ = JointSample(joints_.size());
  state_.positions = positions;
  command_ = state_;
}
}  // namespace vrrw_control
