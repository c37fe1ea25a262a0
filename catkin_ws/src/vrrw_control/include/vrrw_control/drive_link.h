#pragma once
#include <string>
#include <vector>
#include <vrrw_control/joint_sample.h>

namespace vrrw_control
{
/// \brief Where a real robot's measured state comes from (its driver's joint_states).
class DriveLink
{
public:
  virtual ~DriveLink() = default;
  /// \brief Copies the newest measured state of the joints; false while some joint was never measured.
  virtual bool latestState(const std::vector<std::string>& joints, JointSample& state,
                           std::vector<double>& efforts) = 0;
};
}  // namespace vrrw_control
