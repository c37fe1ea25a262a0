#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_kinematics
{
/// \brief Limits and sampling of a time parameterization.
struct TimingOptions
{
  std::vector<double> max_velocity;      ///< per joint (rad/s, m/s), from the URDF
  std::vector<double> max_acceleration;  ///< per joint, from the scene (armAccelerationLimits)
  double max_deviation = 0.02;  ///< how far (joint space) the blend at a waypoint may cut the corner; 0: stop there
  double sample_period = 0.01;  ///< s between trajectory points
  double path_step = 1e-3;      ///< arc-length grid of the phase-plane integration
  double safety = 0.98;         ///< fraction of the limits the integration aims at
  /// s: the longest trajectory timed; a longer one is refused before it is sampled (a request's cost is
  /// bounded: max_velocity_scaling_factor 1e-6 asked for 47 M points). 600 s = 60 001 points at 10 ms (about
  /// 9 MB for a 6-joint arm): ten minutes covers any motion a person would wait for.
  double max_duration = 600.0;
};

/// \brief Throws KinematicsError(InvalidArgument) when a trajectory of `duration` s exceeds
/// options.max_duration, with the figures and the limit in the message.
void checkDuration(double duration, const TimingOptions& options);

/// \brief Time-optimal time parameterization of a waypoint path (T. Kunz and M. Stilman, "Time-Optimal
/// Trajectory Generation for Path Following with Bounded Acceleration and Velocity", RSS 2012).
///
/// Corners get circular blends (at most max_deviation from the waypoint); the maximum path velocity
/// under joint velocity and acceleration limits is integrated forward and backward on an arc-length
/// grid. The trajectory starts and ends at rest with strictly increasing times.
class TimeParameterization
{
public:
  explicit TimeParameterization(const TimingOptions& options);
  /// \brief Throws KinematicsError(InvalidArgument) for bad limits or a path of the wrong width.
  vrrw_trajectory::JointTrajectory compute(const std::vector<Eigen::VectorXd>& path,
                                           const std::vector<std::string>& joint_names) const;

private:
  TimingOptions options_;
};

/// \brief How a planned path is timed.
enum class TimeProfile
{
  TimeOptimal,  ///< TimeParameterization: as fast as the limits allow, corners blended (steps in acceleration)
  MinimumJerk,  ///< rest to rest along every straight piece of the path, acceleration smooth and zero at both ends
};
/// \brief "" or "time_optimal", "minimum_jerk"; throws KinematicsError(InvalidArgument) naming `field` otherwise.
TimeProfile timeProfile(const std::string& name, const std::string& field = "time_profile");

/// \brief The minimum-jerk blend 10 s^3 - 15 s^4 + 6 s^5 of s in [0, 1].
double minimumJerk(double s);

/// \brief The path timed piece by piece with the minimum-jerk blend 10 s^3 - 15 s^4 + 6 s^5 (T. Flash and
/// N. Hogan, 1985), each piece as short as the joint velocity and acceleration limits allow (peaks 1.875 d / T
/// and 5.774 d / T^2 for a joint moving d), stopping at every vertex. For loads that a step in acceleration
/// sets swinging (an object held by friction between two fingers). Throws as TimeParameterization::compute.
vrrw_trajectory::JointTrajectory minimumJerkTrajectory(const std::vector<Eigen::VectorXd>& path,
                                                       const std::vector<std::string>& joint_names,
                                                       const TimingOptions& options);
}  // namespace vrrw_kinematics
