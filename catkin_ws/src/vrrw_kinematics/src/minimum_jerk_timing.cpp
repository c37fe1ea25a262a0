#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/time_parameterization.h"

#include <cmath>

namespace vrrw_kinematics
{
namespace
{
constexpr double kPeakVelocity = 1.875;               // of d / T, at s = 1/2
const double kPeakAcceleration = 10.0 / std::sqrt(3.0);  // of d / T^2, at s = (3 -+ sqrt 3) / 6

/// Shortest duration of a rest-to-rest minimum-jerk move by `delta` within the limits.
double pieceDuration(const Eigen::VectorXd& delta, const TimingOptions& options)
{
  double duration = 0.0;
  for (Eigen::Index j = 0; j < delta.size(); ++j)
  {
    const double d = std::abs(delta[j]);
    const double v = options.safety * options.max_velocity[std::size_t(j)];
    const double a = options.safety * options.max_acceleration[std::size_t(j)];
    duration = std::max({ duration, kPeakVelocity * d / v, std::sqrt(kPeakAcceleration * d / a) });
  }
  return duration;
}

void append(vrrw_trajectory::JointTrajectory& trajectory, double time, const Eigen::VectorXd& q,
            const Eigen::VectorXd& v, const Eigen::VectorXd& a)
{
  trajectory.points.push_back({ time, std::vector<double>(q.data(), q.data() + q.size()),
                                std::vector<double>(v.data(), v.data() + v.size()),
                                std::vector<double>(a.data(), a.data() + a.size()) });
}
}  // namespace

double minimumJerk(double s)
{
  return s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
}

TimeProfile timeProfile(const std::string& name, const std::string& field)
{
  if (name.empty() || name == "time_optimal")
    return TimeProfile::TimeOptimal;
  if (name == "minimum_jerk")
    return TimeProfile::MinimumJerk;
  throw KinematicsError(ErrorCode::InvalidArgument,
                        field + ": '" + name + "': unknown (time_optimal, the default, or minimum_jerk)");
}

vrrw_trajectory::JointTrajectory minimumJerkTrajectory(const std::vector<Eigen::VectorXd>& path,
                                                       const std::vector<std::string>& joint_names,
                                                       const TimingOptions& options)
{
  const std::size_t n = joint_names.size();
  if (options.max_velocity.size() != n || options.max_acceleration.size() != n || path.empty())
    throw KinematicsError(ErrorCode::InvalidArgument, "minimum-jerk timing: " + std::to_string(n) + " joints, " +
                                                          std::to_string(options.max_velocity.size()) + " limits, " +
                                                          std::to_string(path.size()) + " path points");
  for (std::size_t j = 0; j < n; ++j)
    if (!(options.max_velocity[j] > 0.0) || !(options.max_acceleration[j] > 0.0))
      throw KinematicsError(ErrorCode::InvalidArgument, "minimum-jerk timing: " + joint_names[j] + ": limits must be positive");
  double total = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k)
    total += pieceDuration(path[k] - path[k - 1], options);
  checkDuration(total, options);
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = joint_names;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(Eigen::Index(n));
  append(trajectory, 0.0, path.front(), zero, zero);
  double time = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k)
  {
    const Eigen::VectorXd delta = path[k] - path[k - 1];
    const double duration = pieceDuration(delta, options);
    if (duration < 1e-9)
      continue;  // a repeated vertex
    const int samples = std::max(2, int(std::ceil(duration / options.sample_period)));
    for (int i = 1; i <= samples; ++i)
    {
      const double s = double(i) / samples;
      const double rate = 30.0 * s * s * (1.0 - s) * (1.0 - s) / duration;
      const double curve = 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s) / (duration * duration);
      append(trajectory, time + s * duration, i == samples ? path[k] : Eigen::VectorXd(path[k - 1] + minimumJerk(s) * delta),
             rate * delta, curve * delta);
    }
    time += duration;
  }
  return trajectory;
}
}  // namespace vrrw_kinematics
