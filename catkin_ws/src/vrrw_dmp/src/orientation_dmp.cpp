// OrientationDmp: learning (check, differentiate the quaternion, choose each axis' scaling, regress) and
// the rollout's midpoint steps.
#include <vrrw_dmp/orientation_dmp.h>

#include <algorithm>
#include <cmath>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/local_polynomial_derivative.h>
#include <vrrw_dmp/quaternion_maps.h>

#include "forcing_regression.h"
#include "format_number.h"

namespace vrrw_dmp
{
namespace
{
const char* const kAxes[] = { "x", "y", "z" };

/// Unit-norm tolerance of a demonstrated or loaded quaternion.
constexpr double kUnitTolerance = 1e-6;

void checkQuaternion(const Eigen::Quaterniond& q, const std::string& what)
{
  const double norm = q.coeffs().norm();
  if (!q.coeffs().allFinite())
    throw DmpError(what + ": not finite");
  if (std::abs(norm - 1.0) > kUnitTolerance)
    throw DmpError(what + ": norm " + format(norm) + " is not 1 (a unit quaternion is needed)");
}

/// The demonstration's quaternions, normalised, each on the same side as its predecessor (q ~ -q).
std::vector<Eigen::Quaterniond> continuous(const std::vector<double>& times,
                                           const std::vector<Eigen::Quaterniond>& orientations)
{
  if (times.size() != orientations.size())
    throw DmpError("orientation demo: " + std::to_string(orientations.size()) + " orientations for " +
                   std::to_string(times.size()) + " times");
  if (times.size() < 3)
    throw DmpError("orientation demo: " + std::to_string(times.size()) + " sample(s), learning needs at least 3");
  std::vector<Eigen::Quaterniond> out;
  out.reserve(orientations.size());
  for (std::size_t k = 0; k < orientations.size(); ++k)
  {
    const std::string where = "orientation demo: sample " + std::to_string(k);
    if (!std::isfinite(times[k]))
      throw DmpError(where + ": time is not finite");
    if (k > 0 && !(times[k] > times[k - 1]))
      throw DmpError(where + ": time " + format(times[k]) + " is not after " + format(times[k - 1]));
    checkQuaternion(orientations[k], where);
    Eigen::Quaterniond q = orientations[k].normalized();
    if (!out.empty() && out.back().coeffs().dot(q.coeffs()) < 0.0)
      q.coeffs() = -q.coeffs();
    out.push_back(q);
  }
  return out;
}
}  // namespace

OrientationDmp OrientationDmp::learn(const std::vector<double>& times,
                                     const std::vector<Eigen::Quaterniond>& orientations,
                                     const DmpParameters& parameters)
{
  parameters.validate();
  const std::vector<Eigen::Quaterniond> q = continuous(times, orientations);
  const std::size_t samples = q.size();
  std::vector<double> t(samples);
  for (std::size_t k = 0; k < samples; ++k)
    t[k] = times[k] - times.front();
  const double duration = t.back();

  // Derivatives of the four components (stride 4: x, y, z, w as Eigen stores them).
  std::vector<double> components(samples * 4), first(samples * 4), second(samples * 4);
  for (std::size_t k = 0; k < samples; ++k)
    std::copy(q[k].coeffs().data(), q[k].coeffs().data() + 4, components.begin() + k * 4);
  const LocalPolynomialDerivative fit(t, derivativeHalfWindow(parameters, samples));
  for (std::size_t c = 0; c < 4; ++c)
    fit.apply(components.data() + c, 4, first.data() + c, second.data() + c);

  // Each axis' scaling from the rotation vector's excursion from the start.
  const Eigen::Quaterniond start = q.front(), goal = q.back();
  Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
  for (const Eigen::Quaterniond& sample : q)
  {
    const Eigen::Vector3d r = rotationBetween(sample, start);
    low = low.cwiseMin(r);
    high = high.cwiseMax(r);
  }
  const Eigen::Vector3d amplitude = high - low;
  const Eigen::Vector3d offset = rotationBetween(goal, start);
  std::vector<AmplitudeScaling> scaling(3);
  std::vector<std::string> warnings;
  Eigen::Vector3d scale;
  for (int a = 0; a < 3; ++a)
  {
    bool degenerate = false;
    scaling[a] = scalingFor(offset[a], amplitude[a], parameters, degenerate);
    if (degenerate && scaling[a] == AmplitudeScaling::goal_offset)
      warnings.push_back(std::string("orientation axis ") + kAxes[a] + ": the rotation from start to goal (" +
                         format(offset[a]) + " rad) is within " + format(100.0 * parameters.degenerate_ratio) +
                         "% of its range " + format(amplitude[a]) +
                         ", so the forcing term (scaled by it) vanishes or explodes on a new goal; learn with "
                         "scaling 'auto' or 'amplitude'");
    scale[a] = scaling[a] == AmplitudeScaling::goal_offset ? offset[a] : (amplitude[a] > 0.0 ? amplitude[a] : 1.0);
  }

  // Target forcing terms: tau deta/dt + D eta - K 2 log(g * conj(q)), eta = tau omega.
  const double K = parameters.K, D = parameters.damping();
  std::vector<double> targets(samples * 3);
  for (std::size_t k = 0; k < samples; ++k)
  {
    const Eigen::Quaterniond qd(Eigen::Vector4d(first.data() + k * 4));
    const Eigen::Quaterniond qdd(Eigen::Vector4d(second.data() + k * 4));
    const Eigen::Vector3d omega = 2.0 * (qd * q[k].conjugate()).vec();
    const Eigen::Vector3d omega_dot = 2.0 * ((qdd * q[k].conjugate()).coeffs() + (qd * qd.conjugate()).coeffs())
                                                .head<3>();
    const Eigen::Vector3d force = duration * duration * omega_dot + D * duration * omega -
                                  K * rotationBetween(goal, q[k]);
    for (int a = 0; a < 3; ++a)
      targets[k * 3 + a] = scale[a] != 0.0 ? force[a] / scale[a] : 0.0;
  }
  GaussianBasis basis(parameters.basis_count, parameters.alpha);
  auto weights = regressForcing(t, 3, targets, basis, parameters.alpha);
  return OrientationDmp(parameters, std::move(basis), std::move(weights), start, goal, amplitude, std::move(scaling),
                        duration, std::move(warnings));
}

OrientationDmp::OrientationDmp(DmpParameters parameters, GaussianBasis basis, std::vector<std::vector<double>> weights,
                               Eigen::Quaterniond demo_start, Eigen::Quaterniond demo_goal,
                               Eigen::Vector3d demo_amplitude, std::vector<AmplitudeScaling> axis_scaling,
                               double demo_duration, std::vector<std::string> warnings)
  : parameters_(parameters)
  , basis_(std::move(basis))
  , weights_(std::move(weights))
  , demo_start_(demo_start)
  , demo_goal_(demo_goal)
  , demo_amplitude_(demo_amplitude)
  , axis_scaling_(std::move(axis_scaling))
  , demo_duration_(demo_duration)
  , warnings_(std::move(warnings))
{
  parameters_.validate();
  if (basis_.size() != parameters_.basis_count || basis_.widths().size() != basis_.size())
    throw DmpError("orientation model: " + std::to_string(basis_.size()) + " basis centres for N = " +
                   std::to_string(parameters_.basis_count));
  checkQuaternion(demo_start_, "orientation model: demo start");
  checkQuaternion(demo_goal_, "orientation model: demo goal");
  if (!demo_amplitude_.allFinite())
    throw DmpError("orientation model: demo amplitude is not finite");
  if (weights_.size() != 3 || axis_scaling_.size() != 3)
    throw DmpError("orientation model: weights and scaling are needed for the 3 axes");
  for (int a = 0; a < 3; ++a)
  {
    if (weights_[a].size() != basis_.size())
      throw DmpError(std::string("orientation model: weights of axis ") + kAxes[a] + ": " +
                     std::to_string(weights_[a].size()) + " values for " + std::to_string(basis_.size()) +
                     " basis functions");
    for (double w : weights_[a])
      if (!std::isfinite(w))
        throw DmpError(std::string("orientation model: weights of axis ") + kAxes[a] + ": not finite");
    if (axis_scaling_[a] == AmplitudeScaling::automatic)
      throw DmpError(std::string("orientation model: axis ") + kAxes[a] + " scaling must be goal or amplitude");
  }
  if (!(demo_duration_ > 0.0) || !std::isfinite(demo_duration_))
    throw DmpError("orientation model: demo duration " + format(demo_duration_) + " must be > 0");
}

OrientationState OrientationDmp::begin(const Eigen::Quaterniond& start, const Eigen::Quaterniond& goal,
                                       double tau) const
{
  checkQuaternion(start, "orientation start");
  checkQuaternion(goal, "orientation goal");
  if (!(tau > 0.0) || !std::isfinite(tau))
    throw DmpError("tau = " + format(tau) + ": must be a finite number > 0");
  OrientationState state;
  state.tau = tau;
  state.orientation = start.normalized();
  state.goal = goal.normalized();
  const Eigen::Vector3d offset = rotationBetween(state.goal, state.orientation);
  for (int a = 0; a < 3; ++a)
    state.scale[a] = axis_scaling_[a] == AmplitudeScaling::goal_offset
                         ? offset[a]
                         : (demo_amplitude_[a] > 0.0 ? demo_amplitude_[a] : 1.0);
  state.psi.resize(basis_.size());
  state.eta_rate = etaRate(state, state.orientation, state.eta, state.phase);
  state.angular_acceleration = state.eta_rate / tau;
  return state;
}

Eigen::Vector3d OrientationDmp::forcingAt(double s, double* psi) const
{
  std::size_t first = 0;
  std::size_t last = 0;
  basis_.evaluate(s, psi, first, last);
  double sum = 0.0;
  for (std::size_t i = first; i < last; ++i)
    sum += psi[i];
  const double fade = tailFade(s, parameters_.alpha);
  Eigen::Vector3d forcing;
  for (int a = 0; a < 3; ++a)
  {
    double blend = 0.0;
    for (std::size_t i = first; i < last; ++i)
      blend += weights_[a][i] * psi[i];
    forcing[a] = blend * s / sum * fade;
  }
  return forcing;
}

Eigen::Vector3d OrientationDmp::etaRate(OrientationState& state, const Eigen::Quaterniond& q,
                                        const Eigen::Vector3d& eta, double s) const
{
  const Eigen::Vector3d forcing = forcingAt(s, state.psi.data());
  return (parameters_.K * rotationBetween(state.goal, q) - parameters_.damping() * eta +
          state.scale.cwiseProduct(forcing)) /
         state.tau;
}

void OrientationDmp::step(OrientationState& state, double dt) const
{
  if (dt != state.step_dt)
  {
    const double spacing = state.tau / static_cast<double>(std::max<std::size_t>(basis_.size(), 2) - 1);
    const double longest = kMaxSubstep * std::min(spacing, state.tau / std::sqrt(parameters_.K));
    state.step_dt = dt;
    state.substeps = static_cast<std::size_t>(std::ceil(dt / longest));
    state.h = dt / static_cast<double>(state.substeps);
  }
  for (std::size_t i = 0; i < state.substeps; ++i)
    integrate(state);
  state.time += dt;
}

void OrientationDmp::integrate(OrientationState& state) const
{
  const double h = state.h;
  const double tau = state.tau;
  const double decay = parameters_.alpha / tau;
  const double s_mid = state.phase * std::exp(-0.5 * decay * h);
  // explicit midpoint: the rates at the step's middle move the whole step
  const Eigen::Vector3d eta_mid = state.eta + 0.5 * h * state.eta_rate;
  const Eigen::Quaterniond q_mid = (quaternionExp(0.25 * h / tau * state.eta) * state.orientation).normalized();
  const Eigen::Vector3d rate_mid = etaRate(state, q_mid, eta_mid, s_mid);
  state.eta += h * rate_mid;
  state.orientation = (quaternionExp(0.5 * h / tau * eta_mid) * state.orientation).normalized();
  state.phase *= std::exp(-decay * h);
  state.angular_velocity = state.eta / tau;
  state.eta_rate = etaRate(state, state.orientation, state.eta, state.phase);
  state.angular_acceleration = state.eta_rate / tau;
}
}  // namespace vrrw_dmp
