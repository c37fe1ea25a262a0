#pragma once
#include <string>
#include <vector>
#include <vrrw_control/joint_sample.h>

namespace vrrw_control
{
/// \brief Transport to a simulated or real drive: sends targets, returns the latest measured state.
class DriveLink
{
public:
  virtual ~DriveLink() = default;
  /// \brief Streams position and velocity targets of the joints (robot order) with their drive
  /// force limits (0: the configured limit).
  virtual void sendTargets(const std::vector<std::string>& joints, const JointSample& targets,
                           const std::vector<double>& effort_limits, double time) = 0;
  /// \brief Copies the newest measured state of the joints; false while some joint was never measured.
  virtual bool latestState(const std::vector<std::string>& joints, JointSample& state,
                           std::vector<double>& efforts) = 0;
  /// \brief Seconds (wall clock) since the newest measured state arrived; infinity before the first.
  virtual double stateAge() const = 0;
};
}  // namespace vrrw_control
