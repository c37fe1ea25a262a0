// Dmp::learn: a demonstration becomes forcing-term weights in four stages (check, differentiate,
// choose each joint's scaling, regress the weights), each its own function below.
#include <vrrw_dmp/dmp.h>

#include <algorithm>
#include <cmath>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/local_polynomial_derivative.h>

#include "forcing_regression.h"
#include "format_number.h"

namespace vrrw_dmp
{
namespace
{
/// The demonstration as flat arrays, sample-major (value of joint j at sample k: [k * joints + j]).
struct DemoKinematics
{
  std::size_t joints = 0;
  std::size_t samples = 0;
  double duration = 0.0;
  std::vector<double> times;  ///< from 0
  std::vector<double> y;
  std::vector<double> yd;
  std::vector<double> ydd;

  double at(const std::vector<double>& values, std::size_t k, std::size_t j) const { return values[k * joints + j]; }
};

/// How each joint's forcing term is scaled, with what learning found worth a warning.
struct JointScaling
{
  std::vector<double> amplitude;  ///< demonstrated range max - min
  std::vector<AmplitudeScaling> scaling;
  std::vector<double> scale;  ///< the factor itself: g - x0, or the range
  std::vector<std::string> warnings;
};

void checkDemo(const vrrw_trajectory::JointTrajectory& demo)
{
  const std::size_t n = demo.joint_names.size();
  if (n == 0)
    throw DmpError("demo: no joints");
  if (demo.points.size() < 3)
    throw DmpError("demo: " + std::to_string(demo.points.size()) + " sample(s), learning needs at least 3");
  auto where = [](std::size_t k) { return "demo: sample " + std::to_string(k) + ": "; };
  for (std::size_t k = 0; k < demo.points.size(); ++k)
  {
    const auto& point = demo.points[k];
    if (point.positions.size() != n)
      throw DmpError(where(k) + std::to_string(point.positions.size()) + " positions for " + std::to_string(n) +
                     " joints");
    if (!std::isfinite(point.time))
      throw DmpError(where(k) + "time is not finite");
    if (k > 0 && !(point.time > demo.points[k - 1].time))
      throw DmpError(where(k) + "time " + format(point.time) + " is not after " + format(demo.points[k - 1].time));
    for (std::size_t j = 0; j < n; ++j)
      if (!std::isfinite(point.positions[j]))
        throw DmpError(where(k) + "joint '" + demo.joint_names[j] + "' position is not finite");
  }
}

/// Sample times from 0.
std::vector<double> demoTimes(const vrrw_trajectory::JointTrajectory& demo)
{
  std::vector<double> times(demo.points.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    times[k] = demo.points[k].time - demo.points.front().time;
  return times;
}

/// Velocities and accelerations from the positions alone (recorded velocities are often missing or
/// lag the positions), by a LocalPolynomialDerivative \a fit at the true, possibly jittery, \a times.
DemoKinematics differentiate(const vrrw_trajectory::JointTrajectory& demo, std::vector<double> times,
                             const LocalPolynomialDerivative& fit)
{
  DemoKinematics kinematics;
  const std::size_t n = demo.joint_names.size();
  const std::size_t samples = demo.points.size();
  kinematics.joints = n;
  kinematics.samples = samples;
  kinematics.duration = times.back();
  kinematics.times = std::move(times);
  kinematics.y.resize(samples * n);
  for (std::size_t k = 0; k < samples; ++k)
    std::copy(demo.points[k].positions.begin(), demo.points[k].positions.end(), kinematics.y.begin() + k * n);
  kinematics.yd.resize(samples * n);
  kinematics.ydd.resize(samples * n);
  for (std::size_t j = 0; j < n; ++j)
    fit.apply(kinematics.y.data() + j, n, kinematics.yd.data() + j, kinematics.ydd.data() + j);
  return kinematics;
}

double demonstratedRange(const DemoKinematics& kinematics, std::size_t j)
{
  double low = kinematics.at(kinematics.y, 0, j);
  double high = low;
  for (std::size_t k = 0; k < kinematics.samples; ++k)
  {
    low = std::min(low, kinematics.at(kinematics.y, k, j));
    high = std::max(high, kinematics.at(kinematics.y, k, j));
  }
  return high - low;
}

std::string degenerateWarning(const std::string& joint, double offset, double amplitude, double ratio,
                              AmplitudeScaling scaling)
{
  const std::string found = "joint '" + joint + "': g - x0 = " + format(offset) + " is within " +
                            format(100.0 * ratio) + "% of the demonstrated range";
  if (scaling != AmplitudeScaling::goal_offset)
    return found + "; its forcing term is scaled by the range " + format(amplitude);
  return found + " " + format(amplitude) + ", so the forcing term (scaled by g - x0) " +
         (offset == 0.0 ? "vanishes and the motion is lost" : "explodes on a new goal") +
         "; learn with scaling 'auto' or 'amplitude' to scale by the demonstrated range instead";
}

/// The paper's g - x0 per joint, or the demonstrated range where the parameters ask for it (or, with
/// automatic, where g - x0 is too small a part of the motion to scale by).
JointScaling chooseScaling(const DemoKinematics& kinematics, const std::vector<std::string>& names,
                           const std::vector<double>& start, const std::vector<double>& goal,
                           const DmpParameters& parameters)
{
  const std::size_t n = kinematics.joints;
  JointScaling result;
  result.amplitude.resize(n);
  result.scaling.resize(n);
  result.scale.resize(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    const double amplitude = demonstratedRange(kinematics, j);
    const double offset = goal[j] - start[j];
    bool degenerate = false;
    const AmplitudeScaling scaling = scalingFor(offset, amplitude, parameters, degenerate);
    if (degenerate)
      result.warnings.push_back(degenerateWarning(names[j], offset, amplitude, parameters.degenerate_ratio, scaling));
    result.amplitude[j] = amplitude;
    result.scaling[j] = scaling;
    if (scaling == AmplitudeScaling::goal_offset)
      result.scale[j] = offset;
    else
      result.scale[j] = amplitude > 0.0 ? amplitude : 1.0;
  }
  return result;
}

/// The transformation system solved for f with tau = the demonstration's duration, per sample and joint,
/// divided by the joint's scale (sample-major), then regressed on the basis (regressForcing).
std::vector<std::vector<double>> regressWeights(const DemoKinematics& kinematics, const std::vector<double>& goal,
                                                const std::vector<double>& scale, const GaussianBasis& basis,
                                                const DmpParameters& parameters)
{
  const std::size_t n = kinematics.joints;
  const double duration = kinematics.duration;
  const double K = parameters.K;
  const double D = parameters.damping();
  std::vector<double> targets(kinematics.samples * n);
  for (std::size_t k = 0; k < kinematics.samples; ++k)
    for (std::size_t j = 0; j < n; ++j)
    {
      const std::size_t at = k * n + j;
      const double force = duration * duration * kinematics.ydd[at] - K * (goal[j] - kinematics.y[at]) +
                           D * duration * kinematics.yd[at];
      targets[at] = scale[j] != 0.0 ? force / scale[j] : 0.0;
    }
  return regressForcing(kinematics.times, n, targets, basis, parameters.alpha);
}

/// FNV-1a over the 64-bit patterns of the demonstration's times and positions.
std::string checksum(const vrrw_trajectory::JointTrajectory& demo)
{
  std::vector<double> values;
  for (const auto& point : demo.points)
  {
    values.push_back(point.time);
    values.insert(values.end(), point.positions.begin(), point.positions.end());
  }
  return checksumOf(values);
}

DmpProvenance stamped(DmpProvenance provenance, const vrrw_trajectory::JointTrajectory& demo)
{
  if (provenance.created.empty())
    provenance.created = utcNow();
  provenance.samples = demo.points.size();
  provenance.demo_checksum = checksum(demo);
  return provenance;
}
}  // namespace

Dmp Dmp::learn(const vrrw_trajectory::JointTrajectory& demo, const DmpParameters& parameters,
               const DmpProvenance& provenance)
{
  parameters.validate();
  checkDemo(demo);
  std::vector<double> times = demoTimes(demo);
  const LocalPolynomialDerivative fit(times, derivativeHalfWindow(parameters, times.size()));
  const DemoKinematics kinematics = differentiate(demo, std::move(times), fit);
  const std::size_t n = kinematics.joints;
  std::vector<double> start(kinematics.y.begin(), kinematics.y.begin() + n);
  std::vector<double> goal(kinematics.y.end() - n, kinematics.y.end());
  JointScaling scaling = chooseScaling(kinematics, demo.joint_names, start, goal, parameters);
  GaussianBasis basis(parameters.basis_count, parameters.alpha);
  auto weights = regressWeights(kinematics, goal, scaling.scale, basis, parameters);
  return Dmp(demo.joint_names, parameters, std::move(basis), std::move(weights), std::move(start), std::move(goal),
             std::move(scaling.amplitude), std::move(scaling.scaling), kinematics.duration,
             stamped(provenance, demo), std::move(scaling.warnings));
}
}  // namespace vrrw_dmp
