#include <vrrw_dmp/dmp.h>

#include <algorithm>
#include <cmath>

#include <vrrw_dmp/dmp_error.h>

#include "forcing_regression.h"
#include "format_number.h"

namespace vrrw_dmp
{
namespace
{
void checkVector(const std::vector<double>& values, std::size_t n, const std::string& what,
                 const std::string& per = "joints")
{
  if (values.size() != n)
    throw DmpError(what + ": " + std::to_string(values.size()) + " values for " + std::to_string(n) + " " + per);
  for (std::size_t j = 0; j < n; ++j)
    if (!std::isfinite(values[j]))
      throw DmpError(what + ": value " + std::to_string(j + 1) + " is not finite");
}
}  // namespace

Dmp::Dmp(std::vector<std::string> joint_names, DmpParameters parameters, GaussianBasis basis,
         std::vector<std::vector<double>> weights, std::vector<double> demo_start, std::vector<double> demo_goal,
         std::vector<double> demo_amplitude, std::vector<AmplitudeScaling> joint_scaling, double demo_duration,
         DmpProvenance provenance, std::vector<std::string> warnings)
  : joint_names_(std::move(joint_names))
  , parameters_(parameters)
  , basis_(std::move(basis))
  , weights_(std::move(weights))
  , demo_start_(std::move(demo_start))
  , demo_goal_(std::move(demo_goal))
  , demo_amplitude_(std::move(demo_amplitude))
  , joint_scaling_(std::move(joint_scaling))
  , demo_duration_(demo_duration)
  , provenance_(std::move(provenance))
  , warnings_(std::move(warnings))
{
  parameters_.validate();
  const std::size_t n = joint_names_.size();
  if (n == 0)
    throw DmpError("model: no joints");
  if (basis_.size() != parameters_.basis_count || basis_.widths().size() != basis_.size())
    throw DmpError("model: " + std::to_string(basis_.size()) + " basis centres/" +
                   std::to_string(basis_.widths().size()) + " widths for N = " +
                   std::to_string(parameters_.basis_count));
  checkVector(demo_start_, n, "model: demo start");
  checkVector(demo_goal_, n, "model: demo goal");
  checkVector(demo_amplitude_, n, "model: demo amplitude");
  checkVector(basis_.centers(), basis_.size(), "model: basis centres", "basis functions");
  checkVector(basis_.widths(), basis_.size(), "model: basis widths", "basis functions");
  if (weights_.size() != n || joint_scaling_.size() != n)
    throw DmpError("model: weights or scaling not given for each of the " + std::to_string(n) + " joints");
  for (std::size_t j = 0; j < n; ++j)
  {
    checkVector(weights_[j], basis_.size(), "model: weights of joint '" + joint_names_[j] + "'", "basis functions");
    if (joint_scaling_[j] == AmplitudeScaling::automatic)
      throw DmpError("model: joint '" + joint_names_[j] + "' scaling must be goal or amplitude");
  }
  if (!(demo_duration_ > 0.0) || !std::isfinite(demo_duration_))
    throw DmpError("model: demo duration " + format(demo_duration_) + " must be > 0");
}

std::vector<std::string> Dmp::planWarnings(const RolloutRequest& request) const
{
  const std::size_t n = dofs();
  const std::vector<double>& start = request.start.empty() ? demo_start_ : request.start;
  const std::vector<double>& goal = request.goal.empty() ? demo_goal_ : request.goal;
  checkVector(start, n, "start");
  checkVector(goal, n, "goal");
  const double ratio = parameters_.degenerate_ratio;
  std::vector<std::string> warnings;
  for (std::size_t j = 0; j < n; ++j)
  {
    const double amplitude = demo_amplitude_[j];
    const double demo_offset = demo_goal_[j] - demo_start_[j];
    if (joint_scaling_[j] != AmplitudeScaling::goal_offset || !(amplitude > 0.0) ||
        std::abs(demo_offset) <= ratio * amplitude)
      continue;
    const double offset = goal[j] - start[j];
    const std::string joint = "joint '" + joint_names_[j] + "': ";
    if (std::abs(offset) <= ratio * amplitude)
    {
      warnings.push_back(joint + "new g - x0 = " + format(offset) + " is within " + format(100.0 * ratio) +
                         "% of the demonstrated range " + format(amplitude) +
                         ", so the forcing term (scaled by g - x0) vanishes and the demonstrated shape is lost; "
                         "learn with --scaling amplitude to keep it around any goal");
      continue;
    }
    const double factor = offset / demo_offset;
    if (factor < 0.0 || factor > kMaxGoalScaling)
      warnings.push_back(joint + "goal scaling factor (g - x0)/(g_demo - x0_demo) = " + format(factor) +
                         (factor < 0.0 ? (factor < -kMaxGoalScaling ? " mirrors and amplifies" : " mirrors") :
                                         " amplifies") +
                         " the demonstrated shape (demo g - x0 = " + format(demo_offset) + ", new " +
                         format(offset) + ")");
  }
  return warnings;
}

DmpState Dmp::begin(const std::vector<double>& start, const std::vector<double>& goal, double tau) const
{
  const std::size_t n = dofs();
  checkVector(start, n, "start");
  checkVector(goal, n, "goal");
  if (!(tau > 0.0) || !std::isfinite(tau))
    throw DmpError("tau = " + format(tau) + ": must be a finite number > 0");
  DmpState state;
  state.tau = tau;
  state.positions = start;
  state.velocities.assign(n, 0.0);
  state.accelerations.assign(n, 0.0);
  state.start = start;
  state.goal = goal;
  state.scale.resize(n);
  for (std::size_t j = 0; j < n; ++j)
    state.scale[j] = joint_scaling_[j] == AmplitudeScaling::goal_offset ? goal[j] - start[j] :
                                                                          (demo_amplitude_[j] > 0.0 ? demo_amplitude_[j] : 1.0);
  state.scaled_velocity.assign(n, 0.0);
  state.forcing.resize(n);
  state.forcing_end.resize(n);
  state.psi.resize(basis_.size());
  forcingAt(state.phase, state.psi.data(), state.forcing.data());
  const double K = parameters_.K;
  for (std::size_t j = 0; j < n; ++j)
    state.accelerations[j] = (K * (goal[j] - start[j]) + state.scale[j] * state.forcing[j]) / (tau * tau);
  return state;
}

void Dmp::forcingAt(double s, double* psi, double* forcing) const
{
  std::size_t first = 0;
  std::size_t last = 0;
  basis_.evaluate(s, psi, first, last);
  double sum = 0.0;
  for (std::size_t i = first; i < last; ++i)
    sum += psi[i];
  const double factor = s / sum * tailFade(s, parameters_.alpha);
  for (std::size_t j = 0; j < weights_.size(); ++j)
  {
    const double* w = weights_[j].data();
    double blend = 0.0;
    for (std::size_t i = first; i < last; ++i)
      blend += w[i] * psi[i];
    forcing[j] = blend * factor;
  }
}

void Dmp::step(DmpState& state, double dt) const
{
  if (dt != state.step_dt || state.transition.tau() != state.tau)
  {
    const double spacing = state.tau / static_cast<double>(std::max<std::size_t>(basis_.size(), 2) - 1);
    state.step_dt = dt;
    state.substeps = static_cast<std::size_t>(std::ceil(dt / (kMaxSubstep * spacing)));
    const double h = dt / static_cast<double>(state.substeps);
    state.transition.prepare(parameters_.K, parameters_.damping(), state.tau, h);
    state.phase_decay = std::exp(-parameters_.alpha * h / state.tau);
  }
  for (std::size_t i = 0; i < state.substeps; ++i)
    integrate(state);
  state.time += dt;
}

void Dmp::integrate(DmpState& state) const
{
  const double s_end = state.phase * state.phase_decay;
  forcingAt(s_end, state.psi.data(), state.forcing_end.data());
  const double K = parameters_.K;
  const double D = parameters_.damping();
  const double inverse_tau = 1.0 / state.tau;
  const double inverse_tau2 = inverse_tau * inverse_tau;
  for (std::size_t j = 0; j < dofs(); ++j)
  {
    const double c = state.scale[j];
    const double f1 = state.forcing_end[j];
    double x = state.positions[j];
    double v = state.scaled_velocity[j];
    state.transition.apply(state.goal[j], c * state.forcing[j], c * f1, x, v);
    state.positions[j] = x;
    state.scaled_velocity[j] = v;
    state.velocities[j] = v * inverse_tau;
    state.accelerations[j] = (K * (state.goal[j] - x) - D * v + c * f1) * inverse_tau2;
    state.forcing[j] = f1;
  }
  state.phase = s_end;
}

std::size_t Dmp::nominalSteps(const RolloutRequest& request, double tau) const
{
  if (!(request.dt > 0.0) || !std::isfinite(request.dt))
    throw DmpError("dt = " + format(request.dt) + ": must be a finite number > 0");
  if (request.tau < 0.0 || !std::isfinite(request.tau))
    throw DmpError("tau = " + format(request.tau) + ": must be a finite number > 0");
  if (!(request.goal_tolerance > 0.0) || !(request.rest_speed > 0.0))
    throw DmpError("rollout tolerances must be > 0");
  if (request.dt > tau)
    throw DmpError("dt = " + format(request.dt) + " is longer than tau = " + format(tau));
  // in double first: tau / dt may be far beyond any integer type
  const double steps = std::ceil(tau / request.dt - 1e-9);
  if (kSettlingFactor * steps + 1.0 > static_cast<double>(kMaxRolloutSamples))
    throw DmpError("tau = " + format(tau) + " s at dt = " + format(request.dt) + " s needs up to " +
                   format(kSettlingFactor * steps + 1.0) + " samples (" + std::to_string(kSettlingFactor) +
                   " tau / dt, settling included), more than the limit of " + std::to_string(kMaxRolloutSamples) +
                   ": raise dt or shorten tau");
  return static_cast<std::size_t>(steps);
}

vrrw_trajectory::JointTrajectory Dmp::rollout(const RolloutRequest& request) const
{
  const double tau = request.tau > 0.0 ? request.tau : demo_duration_;
  const std::size_t nominal_steps = nominalSteps(request, tau);
  DmpState state = begin(request.start.empty() ? demo_start_ : request.start,
                         request.goal.empty() ? demo_goal_ : request.goal, tau);
  const std::size_t max_steps = kSettlingFactor * nominal_steps;
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = joint_names_;
  trajectory.points.reserve(nominal_steps + nominal_steps / 2 + 1);
  for (std::size_t k = 0;; ++k)
  {
    trajectory.points.push_back({ static_cast<double>(k) * request.dt, state.positions, state.velocities,
                                  state.accelerations });
    if (k >= max_steps)
      break;
    if (k >= nominal_steps)
    {
      bool settled = true;
      for (std::size_t j = 0; j < dofs() && settled; ++j)
        settled = std::abs(state.goal[j] - state.positions[j]) <= request.goal_tolerance &&
                  std::abs(state.velocities[j]) <= request.rest_speed;
      if (settled)
        break;
    }
    step(state, request.dt);
  }
  return trajectory;
}
}  // namespace vrrw_dmp
