#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <vrrw_dmp/dmp_parameters.h>
#include <vrrw_dmp/gaussian_basis.h>

namespace vrrw_dmp
{
/// \brief Integration state of an orientation rollout; created by OrientationDmp::begin, advanced by
/// OrientationDmp::step without allocating.
struct OrientationState
{
  double time = 0.0;   ///< seconds since the start
  double phase = 1.0;  ///< canonical variable s
  double tau = 1.0;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< q, unit
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();      ///< omega (rad/s, world axes)
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  ///< d omega / dt (rad/s^2)
  Eigen::Quaterniond goal = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();  ///< what multiplies each axis' forcing term
  Eigen::Vector3d eta = Eigen::Vector3d::Zero();    ///< tau omega
  Eigen::Vector3d eta_rate = Eigen::Vector3d::Zero();  ///< d eta / dt here
  std::vector<double> psi;                          ///< scratch: basis values
  double step_dt = 0.0;                             ///< the last dt given to step(), and for it:
  std::size_t substeps = 1;                         ///< internal steps of length h
  double h = 0.0;
};

/// \brief The unit-quaternion DMP of Ude, Nemec, Petric and Morimoto, "Orientation in Cartesian space
/// dynamic movement primitives", ICRA 2014 (eqs. 18-20), with the basis, phase and learning of Dmp:
///   tau deta/dt = K 2 log(g * conj(q)) - D eta + S f(s),   tau dq/dt = 1/2 eta * q,   tau ds/dt = -alpha s,
/// eta = tau omega, f(s) = sum_i w_i psi_i(s) / sum_i psi_i(s) * s per axis (world axes). No Euler angles:
/// orientation errors are rotation vectors (quaternionLog), steps are quaternion exponentials, so q stays a
/// unit quaternion (renormalised every step: its norm is 1 to rounding).
///
/// S per axis is Ude's diag(2 log(g * conj(q0))) (AmplitudeScaling::goal_offset) or the demonstration's
/// range of the rotation vector from the start about that axis (demo_amplitude); `automatic` takes the range
/// for the axes where the goal offset is within degenerate_ratio of it (a rotation that returns, or none),
/// exactly as Dmp does per joint.
///
/// Learning: the quaternion's components are differentiated by LocalPolynomialDerivative;
/// omega = 2 vec(dq/dt * conj(q)), domega/dt = 2 vec(d2q/dt2 * conj(q) + dq/dt * conj(dq/dt)); the target
/// forcing term follows from the first equation with tau = the demonstration's duration and is regressed
/// on the basis as Dmp's. Rollout: explicit midpoint steps on (eta, q), steps longer than a tenth of the
/// basis spacing or of 1/sqrt(K) tau split internally.
class OrientationDmp
{
public:
  /// \brief Learns from orientations at strictly increasing finite times (>= 3 samples, each quaternion
  /// of norm 1 within 1e-6; q and -q alike). Throws DmpError naming the sample.
  static OrientationDmp learn(const std::vector<double>& times, const std::vector<Eigen::Quaterniond>& orientations,
                              const DmpParameters& parameters);

  /// \brief Sets every field (the model loader); validates sizes and unit quaternions. Throws DmpError.
  OrientationDmp(DmpParameters parameters, GaussianBasis basis, std::vector<std::vector<double>> weights,
                 Eigen::Quaterniond demo_start, Eigen::Quaterniond demo_goal, Eigen::Vector3d demo_amplitude,
                 std::vector<AmplitudeScaling> axis_scaling, double demo_duration,
                 std::vector<std::string> warnings = {});

  /// \brief A fresh state at \a start (at rest) heading for \a goal; allocates. Throws DmpError.
  OrientationState begin(const Eigen::Quaterniond& start, const Eigen::Quaterniond& goal, double tau) const;
  /// \brief Advances \a state by \a dt seconds. Allocation-free.
  void step(OrientationState& state, double dt) const;

  const DmpParameters& parameters() const { return parameters_; }
  const GaussianBasis& basis() const { return basis_; }
  /// \brief weights()[axis][basis], axes x, y, z of the world.
  const std::vector<std::vector<double>>& weights() const { return weights_; }
  const Eigen::Quaterniond& demoStart() const { return demo_start_; }
  const Eigen::Quaterniond& demoGoal() const { return demo_goal_; }
  const Eigen::Vector3d& demoAmplitude() const { return demo_amplitude_; }
  /// \brief The scaling each axis uses (never AmplitudeScaling::automatic).
  const std::vector<AmplitudeScaling>& axisScaling() const { return axis_scaling_; }
  double demoDuration() const { return demo_duration_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

private:
  /// Steps longer than this fraction of the basis spacing (in time), or of tau / sqrt(K), are split.
  static constexpr double kMaxSubstep = 0.1;

  Eigen::Vector3d forcingAt(double s, double* psi) const;
  /// d eta / dt at orientation q, eta, phase s, towards the state's goal (its psi is the scratch).
  Eigen::Vector3d etaRate(OrientationState& state, const Eigen::Quaterniond& q, const Eigen::Vector3d& eta,
                          double s) const;
  void integrate(OrientationState& state) const;

  DmpParameters parameters_;
  GaussianBasis basis_;
  std::vector<std::vector<double>> weights_;
  Eigen::Quaterniond demo_start_;
  Eigen::Quaterniond demo_goal_;
  Eigen::Vector3d demo_amplitude_;
  std::vector<AmplitudeScaling> axis_scaling_;
  double demo_duration_ = 0.0;
  std::vector<std::string> warnings_;
};
}  // namespace vrrw_dmp
