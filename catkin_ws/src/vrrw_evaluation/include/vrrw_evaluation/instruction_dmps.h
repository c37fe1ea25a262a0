#pragma once
#include <map>
#include <string>
#include <vector>
#include <vrrw_dmp/dmp.h>

#include <vrrw_evaluation/demonstration.h>

namespace vrrw_evaluation
{
/// \brief One DMP per arm instruction of a demonstration (the paper learns per instruction, so that a new
/// object pose changes the goals of near-pick and pick while the shape of each motion is kept).
class InstructionDmps
{
public:
  /// \brief Learns every arm instruction of `demo`; throws vrrw_dmp::DmpError or std::invalid_argument.
  InstructionDmps(const Demonstration& demo, const vrrw_dmp::DmpParameters& parameters);

  /// \brief The arm instructions learned, in order.
  const std::vector<std::string>& instructions() const { return names_; }
  const vrrw_dmp::Dmp& dmp(const std::string& instruction) const;
  /// \brief RMS over joints and samples of the rollout with the demonstrated start and goal against the
  /// demonstration, rad.
  double fitRmse(const std::string& instruction) const { return fit_rmse_.at(instruction); }

  /// rad: a rollout past tau this close to its goal ends there (at rest 0.2 s later).
  static constexpr double kSettledWithin = 3e-3;

  /// Fraction of a joint's velocity limit a rollout may reach before it is slowed down.
  static constexpr double kVelocityMargin = 0.9;

  /// \brief The instruction's motion from `start` to `goal` at the demonstrated speed, sampled every dt;
  /// ends exactly at `goal`, at rest. With `max_velocity` (per joint), a rollout that a new goal makes faster
  /// than kVelocityMargin of a limit is slowed down as a whole (a larger tau: the same path, later).
  vrrw_trajectory::JointTrajectory rollout(const std::string& instruction, const std::vector<double>& start,
                                           const std::vector<double>& goal, double dt = 0.01,
                                           const std::vector<double>& max_velocity = {}) const;

private:
  std::vector<std::string> names_;
  std::map<std::string, vrrw_dmp::Dmp> dmps_;
  std::map<std::string, double> fit_rmse_;
};
}  // namespace vrrw_evaluation
