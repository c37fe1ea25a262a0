#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <vrrw_dmp/dmp_parameters.h>
#include <vrrw_dmp/gaussian_basis.h>
#include <vrrw_dmp/spring_damper_step.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_dmp
{
/// \brief Where a model came from, kept with it in the model file.
struct DmpProvenance
{
  std::string source;         ///< e.g. "demo.csv", "bag:/tmp/x.bag#/joint_states", "message"
  std::string created;        ///< UTC, ISO 8601
  std::size_t samples = 0;    ///< demonstration samples
  std::string demo_checksum;  ///< FNV-1a 64 of the demonstration's times and positions, hex
};

/// \brief The current UTC time, ISO 8601: a provenance's `created` (also a skill's).
std::string utcNow();

/// \brief Integration state of a rollout; created by Dmp::begin, advanced by Dmp::step without allocating.
struct DmpState
{
  double time = 0.0;  ///< seconds since the start
  double phase = 1.0;  ///< canonical variable s
  double tau = 1.0;
  std::vector<double> positions;      ///< x (rad)
  std::vector<double> velocities;     ///< dx/dt (rad/s)
  std::vector<double> accelerations;  ///< d2x/dt2 (rad/s^2)
  std::vector<double> start;
  std::vector<double> goal;
  std::vector<double> scale;  ///< what multiplies the forcing term, per joint
  std::vector<double> scaled_velocity;  ///< v = tau dx/dt
  std::vector<double> forcing;          ///< f(s) at the current phase, per joint
  std::vector<double> forcing_end;      ///< scratch: f at the end of the step
  std::vector<double> psi;              ///< scratch: basis values
  double step_dt = 0.0;                 ///< the last dt given to step(), and for it:
  std::size_t substeps = 1;             ///< internal steps of length h
  SpringDamperStep transition;          ///< the exact step over h
  double phase_decay = 1.0;             ///< exp(-alpha h / tau)
};

/// \brief A new start, goal and speed for a rollout; empty vectors and tau <= 0 mean "as demonstrated".
struct RolloutRequest
{
  std::vector<double> start;
  std::vector<double> goal;
  double tau = 0.0;  ///< seconds; the demonstration has tau = its duration
  double dt = 0.01;  ///< output sample period, seconds
  double goal_tolerance = 1e-3;  ///< rad; after tau the rollout ends once every joint is this close to its goal
  double rest_speed = 5e-3;      ///< rad/s ... and every |dx/dt| is below this
};

/// \brief A multi-DoF Dynamic Movement Primitive, equations 2-4 of the VRRW paper (after Ijspeert et
/// al. 2002/2013): per joint  tau dv/dt = K (g - x) - D v + (g - x0) f(s),  tau dx/dt = v,
/// tau ds/dt = -alpha s,  f(s) = sum_i w_i psi_i(s) / sum_i psi_i(s) * s.
///
/// Learning: positions are differentiated with LocalPolynomialDerivative, target forcing terms follow
/// from the first equation with tau = demo duration, and each w_i is the locally weighted regression
///   w_i = sum_k dt_k psi_i(s_k) s_k f_k / sum_k dt_k psi_i(s_k) s_k^2
/// with trapezoid weights dt_k, so that non-uniform sampling does not bias the fit towards dense parts.
///
/// g == x0: with the paper's scaling (g - x0) the forcing term of a joint that returns to its start
/// vanishes (or, nearly there, is hugely amplified on a new goal). learn() detects |g - x0| below
/// degenerate_ratio times the joint's demonstrated range and adds a warning. The remedy is
/// AmplitudeScaling::demo_amplitude (or ::automatic for just those joints): the forcing term is then
/// scaled by the demonstrated range, a constant, and the joint's motion is reproduced around any goal.
/// The same happens at plan time to a joint that was learned with a proper g - x0 when the NEW goal
/// equals its new start, and a new g - x0 of the opposite sign or more than kMaxGoalScaling times the
/// demonstrated one mirrors or amplifies the shape: planWarnings() reports both, per joint.
///
/// After tau (s below exp(-alpha)) the forcing term fades out within a few hundredths of tau: the
/// demonstration says nothing about that time, and what the last basis function extrapolates only holds the
/// system off its goal.
///
/// Rollout: the exact solution of the linear spring-damper over each step with the forcing term
/// linear in between (SpringDamperStep), exact exponential decay of the phase; one forcing
/// evaluation per step. Steps longer than kMaxSubstep of the basis spacing are split internally, so a
/// coarse control period loses no accuracy.
class Dmp
{
public:
  /// \brief Learns from a demonstration (>= 3 samples, strictly increasing finite times, finite
  /// positions; recorded velocities are not used). Throws DmpError naming the problem.
  static Dmp learn(const vrrw_trajectory::JointTrajectory& demo, const DmpParameters& parameters,
                   const DmpProvenance& provenance = {});

  /// \brief Sets every field directly (used by the model loader); validates sizes.
  Dmp(std::vector<std::string> joint_names, DmpParameters parameters, GaussianBasis basis,
      std::vector<std::vector<double>> weights, std::vector<double> demo_start, std::vector<double> demo_goal,
      std::vector<double> demo_amplitude, std::vector<AmplitudeScaling> joint_scaling, double demo_duration,
      DmpProvenance provenance, std::vector<std::string> warnings = {});

  /// \brief Rolls out from t = 0 for tau (the demo's duration scaled), then on until every joint is within
  /// the request's tolerances of its goal (at most kSettlingFactor tau): it ends there, not after the
  /// forcing term's slow decay has crept over the last fraction of a millimetre. Samples every dt. Throws
  /// DmpError for a request whose worst case exceeds kMaxRolloutSamples, before allocating.
  vrrw_trajectory::JointTrajectory rollout(const RolloutRequest& request) const;

  /// \brief One line per concern about rolling out to \a request's start and goal (empty: as
  /// demonstrated), for the joints scaled by g - x0 whose demonstration moved them (|g_demo - x0_demo|
  /// above degenerate_ratio times their range; the others are learn()'s warnings):
  /// - the new |g - x0| is within degenerate_ratio of the demonstrated range: the learned shape vanishes;
  /// - the goal scaling factor (g - x0) / (g_demo - x0_demo) is negative (the shape is mirrored) or above
  ///   kMaxGoalScaling (amplified).
  /// Same format as warnings(). Throws DmpError for a start or goal of the wrong size or not finite.
  std::vector<std::string> planWarnings(const RolloutRequest& request) const;

  /// \brief A fresh state at \a start (at rest) heading for \a goal; allocates. Throws DmpError.
  DmpState begin(const std::vector<double>& start, const std::vector<double>& goal, double tau) const;
  /// \brief Advances \a state by \a dt seconds. Allocation-free; call it from a control loop.
  void step(DmpState& state, double dt) const;

  std::size_t dofs() const { return joint_names_.size(); }
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  const DmpParameters& parameters() const { return parameters_; }
  const GaussianBasis& basis() const { return basis_; }
  /// \brief weights()[joint][basis]
  const std::vector<std::vector<double>>& weights() const { return weights_; }
  const std::vector<double>& demoStart() const { return demo_start_; }
  const std::vector<double>& demoGoal() const { return demo_goal_; }
  const std::vector<double>& demoAmplitude() const { return demo_amplitude_; }
  /// \brief The scaling each joint uses (never AmplitudeScaling::automatic).
  const std::vector<AmplitudeScaling>& jointScaling() const { return joint_scaling_; }
  double demoDuration() const { return demo_duration_; }
  const DmpProvenance& provenance() const { return provenance_; }
  /// \brief One line per concern found while learning (e.g. g == x0 in a joint).
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// A goal scaling factor (g - x0) / (g_demo - x0_demo) above this amplifies the demonstrated shape
  /// enough that planWarnings() reports it.
  static constexpr double kMaxGoalScaling = 3.0;
  /// A rollout lasts at most this many times tau (the settling after tau included).
  static constexpr std::size_t kSettlingFactor = 4;
  /// The most samples a rollout may produce (kSettlingFactor tau / dt + 1): about 270 MB of trajectory
  /// for 6 joints, 250 s at 1 kHz or 2000 s at 125 Hz of tau.
  static constexpr std::size_t kMaxRolloutSamples = 1000000;

private:
  /// Steps longer than this fraction of the basis spacing (in time) are split, so that the forcing
  /// term's bumps are resolved at any dt.
  static constexpr double kMaxSubstep = 0.1;

  /// ceil(tau / dt) of a valid request; throws DmpError naming what is wrong or over the limit.
  std::size_t nominalSteps(const RolloutRequest& request, double tau) const;
  void forcingAt(double s, double* psi, double* forcing) const;
  void integrate(DmpState& state) const;

  std::vector<std::string> joint_names_;
  DmpParameters parameters_;
  GaussianBasis basis_;
  std::vector<std::vector<double>> weights_;
  std::vector<double> demo_start_;
  std::vector<double> demo_goal_;
  std::vector<double> demo_amplitude_;
  std::vector<AmplitudeScaling> joint_scaling_;
  double demo_duration_ = 0.0;
  DmpProvenance provenance_;
  std::vector<std::string> warnings_;
};
}  // namespace vrrw_dmp
