#include "vrrw_kinematics/time_parameterization.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "vrrw_kinematics/kinematics_error.h"

namespace vrrw_kinematics
{
namespace
{
constexpr double kTiny = 1e-9;

/// A piece of the blended path: a straight line or a circular arc, parameterized by arc length.
struct PathPiece
{
  bool circular = false;
  double length = 0.0;
  Eigen::VectorXd origin;     ///< line start, or arc centre
  Eigen::VectorXd direction;  ///< line direction, or arc x
  Eigen::VectorXd normal;     ///< arc y (the tangent at the arc start)
  double radius = 0.0;

  Eigen::VectorXd position(double s) const
  {
    if (!circular)
      return origin + direction * s;
    return origin + radius * (direction * std::cos(s / radius) + normal * std::sin(s / radius));
  }
  Eigen::VectorXd tangent(double s) const
  {
    if (!circular)
      return direction;
    return -direction * std::sin(s / radius) + normal * std::cos(s / radius);
  }
  Eigen::VectorXd curvature(double s) const
  {
    if (!circular)
      return Eigen::VectorXd::Zero(direction.size());
    return -(direction * std::cos(s / radius) + normal * std::sin(s / radius)) / radius;
  }
};

std::vector<PathPiece> blendedPath(const std::vector<Eigen::VectorXd>& waypoints, double max_deviation)
{
  const std::size_t m = waypoints.size();
  std::vector<double> cut(m, 0.0);
  std::vector<PathPiece> blends(m);
  for (std::size_t i = 1; i + 1 < m; ++i)
  {
    const Eigen::VectorXd in = waypoints[i] - waypoints[i - 1], out = waypoints[i + 1] - waypoints[i];
    const Eigen::VectorXd y1 = in.normalized(), y2 = out.normalized();
    const double angle = std::acos(std::max(-1.0, std::min(1.0, y1.dot(y2))));
    if (max_deviation <= 0.0 || angle < 1e-6 || angle > M_PI - 1e-3)
      continue;
    const double half = 0.5 * angle;
    const double l = std::min({ 0.5 * in.norm(), 0.5 * out.norm(),
                                max_deviation * std::sin(half) / (1.0 - std::cos(half)) });
    PathPiece arc;
    arc.circular = true;
    arc.radius = l / std::tan(half);
    arc.origin = waypoints[i] + (y2 - y1).normalized() * arc.radius / std::cos(half);
    arc.direction = (waypoints[i] - l * y1 - arc.origin).normalized();
    arc.normal = y1;
    arc.length = angle * arc.radius;
    cut[i] = l;
    blends[i] = arc;
  }
  std::vector<PathPiece> pieces;
  for (std::size_t i = 0; i + 1 < m; ++i)
  {
    const Eigen::VectorXd direction = (waypoints[i + 1] - waypoints[i]).normalized();
    PathPiece line;
    line.origin = waypoints[i] + cut[i] * direction;
    line.direction = direction;
    line.length = (waypoints[i + 1] - waypoints[i]).norm() - cut[i] - cut[i + 1];
    if (line.length > kTiny)
      pieces.push_back(line);
    if (cut[i + 1] > 0.0)
      pieces.push_back(blends[i + 1]);
  }
  return pieces;
}

class PhasePlane
{
public:
  PhasePlane(const std::vector<double>& velocity, const std::vector<double>& acceleration, double safety)
  {
    for (std::size_t i = 0; i < velocity.size(); ++i)
    {
      v_.push_back(velocity[i] * safety);
      a_.push_back(acceleration[i] * safety);
    }
  }

  /// Largest squared path velocity allowed at a point with path derivatives d1, d2.
  template <typename V>
  double maxSquaredVelocity(const V& d1, const V& d2) const
  {
    double limit = std::numeric_limits<double>::infinity();
    const std::size_t n = v_.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      if (std::abs(d1[i]) > kTiny)
        limit = std::min(limit, (v_[i] / d1[i]) * (v_[i] / d1[i]));
      else if (std::abs(d2[i]) > kTiny)
        limit = std::min(limit, a_[i] / std::abs(d2[i]));
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
      {
        if (i == j || std::abs(d1[i]) <= kTiny || std::abs(d1[j]) <= kTiny)
          continue;
        const double slope = -d2[i] / d1[i] + d2[j] / d1[j];
        if (slope > kTiny)
          limit = std::min(limit, (a_[i] / std::abs(d1[i]) + a_[j] / std::abs(d1[j])) / slope);
      }
    return limit;
  }

  /// Range [lower, upper] of path acceleration at squared path velocity x.
  template <typename V>
  void accelerationRange(const V& d1, const V& d2, double x, double& lower, double& upper) const
  {
    lower = -std::numeric_limits<double>::infinity();
    upper = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < v_.size(); ++i)
    {
      if (std::abs(d1[i]) <= kTiny)
        continue;
      const double bias = -d2[i] * x / d1[i];
      lower = std::max(lower, bias - a_[i] / std::abs(d1[i]));
      upper = std::min(upper, bias + a_[i] / std::abs(d1[i]));
    }
    if (!std::isfinite(upper))
      upper = lower = 0.0;
  }

private:
  std::vector<double> v_;
  std::vector<double> a_;
};

struct Interval
{
  int piece = 0;
  double from = 0.0;  ///< arc length within the piece
  double to = 0.0;
};

/// Path derivatives (tangent d1, curvature d2) at both ends of every grid interval, a column each.
struct GridDerivatives
{
  Eigen::MatrixXd d1_from, d2_from, d1_to, d2_to;
};

/// The path without repeated waypoints; throws for a waypoint that is not `n` finite values.
std::vector<Eigen::VectorXd> distinctWaypoints(const std::vector<Eigen::VectorXd>& path, std::size_t n)
{
  std::vector<Eigen::VectorXd> waypoints;
  for (const Eigen::VectorXd& q : path)
  {
    if (static_cast<std::size_t>(q.size()) != n || !q.allFinite())
      throw KinematicsError(ErrorCode::InvalidArgument, "time parameterization: waypoint " +
                                                            std::to_string(waypoints.size()) +
                                                            " is not " + std::to_string(n) + " finite values");
    if (waypoints.empty() || (q - waypoints.back()).norm() > kTiny)
      waypoints.push_back(q);
  }
  if (waypoints.empty())
    throw KinematicsError(ErrorCode::InvalidArgument, "time parameterization: empty path");
  return waypoints;
}

void appendPoint(vrrw_trajectory::JointTrajectory& trajectory, double t, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd)
{
  vrrw_trajectory::TrajectoryPoint point;
  point.time = t;
  point.positions.assign(q.data(), q.data() + q.size());
  point.velocities.assign(qd.data(), qd.data() + qd.size());
  point.accelerations.assign(qdd.data(), qdd.data() + qdd.size());
  trajectory.points.push_back(point);
}

/// The arc-length grid: `path_step` on blends, where curvature limits the speed, five times coarser on lines.
std::vector<Interval> pathGrid(const std::vector<PathPiece>& pieces, double path_step)
{
  std::vector<Interval> intervals;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const double step = pieces[p].circular ? path_step : 5.0 * path_step;
    const int count = std::max(2, static_cast<int>(std::ceil(pieces[p].length / step)));
    for (int k = 0; k < count; ++k)
      intervals.push_back(Interval{ static_cast<int>(p), pieces[p].length * k / count,
                                    pieces[p].length * (k + 1) / count });
  }
  return intervals;
}

GridDerivatives gridDerivatives(const std::vector<PathPiece>& pieces, const std::vector<Interval>& intervals,
                                std::size_t n)
{
  const std::size_t m = intervals.size();
  const Eigen::Index width = static_cast<Eigen::Index>(n);
  GridDerivatives d{ Eigen::MatrixXd(width, m), Eigen::MatrixXd(width, m), Eigen::MatrixXd(width, m),
                     Eigen::MatrixXd(width, m) };
  for (std::size_t k = 0; k < m; ++k)
  {
    const PathPiece& piece = pieces[intervals[k].piece];
    const Eigen::Index c = static_cast<Eigen::Index>(k);
    d.d1_from.col(c) = piece.tangent(intervals[k].from);
    d.d2_from.col(c) = piece.curvature(intervals[k].from);
    d.d1_to.col(c) = piece.tangent(intervals[k].to);
    d.d2_to.col(c) = piece.curvature(intervals[k].to);
  }
  return d;
}

/// Largest squared path velocity at every grid point: 0 at both ends and at corners the blends left sharp.
std::vector<double> velocityLimitCurve(const GridDerivatives& d, const PhasePlane& plane)
{
  const std::size_t m = static_cast<std::size_t>(d.d1_from.cols());
  std::vector<double> limit(m + 1, 0.0);
  for (std::size_t k = 1; k < m; ++k)
  {
    const Eigen::Index c = static_cast<Eigen::Index>(k);
    const bool corner = (d.d1_to.col(c - 1) - d.d1_from.col(c)).norm() > 1e-6;
    limit[k] = corner ? 0.0
                      : std::min(plane.maxSquaredVelocity(d.d1_to.col(c - 1), d.d2_to.col(c - 1)),
                                 plane.maxSquaredVelocity(d.d1_from.col(c), d.d2_from.col(c)));
  }
  return limit;
}

/// Squared path velocity at every grid point. Integrates forward at the largest and backward at the
/// smallest path acceleration under the limit curve; where the zero-order hold of the path acceleration
/// breaks a true limit at either end of an interval (on blends, where q'' turns), lowers the limit curve
/// there and integrates again.
std::vector<double> squaredPathVelocity(const std::vector<Interval>& intervals, const GridDerivatives& d,
                                        const PhasePlane& plane, const PhasePlane& true_plane,
                                        std::vector<double> limit)
{
  const std::size_t m = intervals.size();
  std::vector<double> x(m + 1, 0.0);
  double lower = 0.0, upper = 0.0;
  for (int pass = 0; pass < 40; ++pass)
  {
    x.assign(m + 1, 0.0);
    for (std::size_t k = 0; k < m; ++k)
    {
      const double ds = intervals[k].to - intervals[k].from;
      const Eigen::Index c = static_cast<Eigen::Index>(k);
      plane.accelerationRange(d.d1_from.col(c), d.d2_from.col(c), x[k], lower, upper);
      x[k + 1] = std::max(0.0, std::min(limit[k + 1], x[k] + 2.0 * ds * std::max(0.0, upper)));
    }
    x[m] = 0.0;
    for (std::size_t k = m; k-- > 0;)
    {
      const double ds = intervals[k].to - intervals[k].from;
      const Eigen::Index c = static_cast<Eigen::Index>(k);
      plane.accelerationRange(d.d1_to.col(c), d.d2_to.col(c), x[k + 1], lower, upper);
      x[k] = std::min(x[k], x[k + 1] - 2.0 * ds * std::min(0.0, lower));
    }
    bool feasible = true;
    for (std::size_t k = 0; k < m; ++k)
    {
      const double ds = intervals[k].to - intervals[k].from;
      const double u = (x[k + 1] - x[k]) / (2.0 * ds);
      const Eigen::Index c = static_cast<Eigen::Index>(k);
      for (const bool at_end : { false, true })
      {
        if (at_end)
          true_plane.accelerationRange(d.d1_to.col(c), d.d2_to.col(c), x[k + 1], lower, upper);
        else
          true_plane.accelerationRange(d.d1_from.col(c), d.d2_from.col(c), x[k], lower, upper);
        if (u < lower - 1e-12 || u > upper + 1e-12)
        {
          feasible = false;
          limit[k] = std::min(limit[k], 0.9 * x[k]);
          limit[k + 1] = std::min(limit[k + 1], 0.9 * x[k + 1]);
        }
      }
    }
    if (feasible)
      break;
  }
  return x;
}

/// Time at every grid point: constant path acceleration across each interval.
std::vector<double> gridTimes(const std::vector<Interval>& intervals, const std::vector<double>& x)
{
  std::vector<double> times(intervals.size() + 1, 0.0);
  for (std::size_t k = 0; k < intervals.size(); ++k)
  {
    const double ds = intervals[k].to - intervals[k].from;
    times[k + 1] = times[k] + 2.0 * ds / std::max(std::sqrt(x[k]) + std::sqrt(x[k + 1]), kTiny);
  }
  return times;
}

/// Points every `period` along the grid's motion, then the goal at rest.
void sampleMotion(const std::vector<PathPiece>& pieces, const std::vector<Interval>& intervals,
                  const std::vector<double>& x, const std::vector<double>& times, double period,
                  const Eigen::VectorXd& goal, vrrw_trajectory::JointTrajectory& trajectory)
{
  const std::size_t m = intervals.size();
  const double duration = times[m];
  std::size_t k = 0;
  for (std::size_t sample = 0;; ++sample)
  {
    const double t = static_cast<double>(sample) * period;
    if (t >= duration - 1e-9)
      break;
    while (k + 1 < m && times[k + 1] <= t)
      ++k;
    const Interval& interval = intervals[k];
    const PathPiece& piece = pieces[interval.piece];
    const double ds = interval.to - interval.from;
    const double u = (x[k + 1] - x[k]) / (2.0 * ds);
    const double tau = t - times[k];
    const double speed = std::max(0.0, std::sqrt(x[k]) + u * tau);
    const double s = std::min(interval.to, interval.from + std::sqrt(x[k]) * tau + 0.5 * u * tau * tau);
    appendPoint(trajectory, t, piece.position(s), piece.tangent(s) * speed,
                piece.tangent(s) * u + piece.curvature(s) * speed * speed);
  }
  const Interval& last = intervals.back();
  const PathPiece& last_piece = pieces[last.piece];
  const double u_last = (x[m] - x[m - 1]) / (2.0 * (last.to - last.from));
  appendPoint(trajectory, duration, goal, Eigen::VectorXd::Zero(goal.size()), last_piece.tangent(last.to) * u_last);
}
}  // namespace

void checkDuration(double duration, const TimingOptions& options)
{
  if (duration <= options.max_duration)
    return;
  char line[256];
  std::snprintf(line, sizeof(line),
                "trajectory: %.4g s (%.4g points at %g s) at these limits; a plan may last at most %g s (%.0f points): "
                "raise max_velocity_scaling_factor or max_acceleration_scaling_factor",
                duration, std::ceil(duration / options.sample_period) + 1.0, options.sample_period, options.max_duration,
                std::floor(options.max_duration / options.sample_period) + 1.0);
  throw KinematicsError(ErrorCode::InvalidArgument, line);
}

TimeParameterization::TimeParameterization(const TimingOptions& options) : options_(options)
{
  const std::size_t n = options.max_velocity.size();
  if (n == 0 || options.max_acceleration.size() != n)
    throw KinematicsError(ErrorCode::InvalidArgument, "time parameterization: velocity and acceleration limits "
                                                      "must be given for every joint");
  for (std::size_t i = 0; i < n; ++i)
    if (!(options.max_velocity[i] > 0.0) || !(options.max_acceleration[i] > 0.0) ||
        !std::isfinite(options.max_velocity[i]) || !std::isfinite(options.max_acceleration[i]))
      throw KinematicsError(ErrorCode::InvalidArgument, "time parameterization: joint " + std::to_string(i) +
                                                            ": limits must be positive and finite");
  if (!(options.sample_period > 0.0) || !(options.path_step > 0.0) || !(options.safety > 0.0) ||
      options.safety > 1.0)
    throw KinematicsError(ErrorCode::InvalidArgument,
                          "time parameterization: sample_period, path_step and safety must be positive");
}

vrrw_trajectory::JointTrajectory TimeParameterization::compute(const std::vector<Eigen::VectorXd>& path,
                                                               const std::vector<std::string>& joint_names) const
{
  const std::size_t n = options_.max_velocity.size();
  if (joint_names.size() != n)
    throw KinematicsError(ErrorCode::InvalidArgument, "time parameterization: " + std::to_string(joint_names.size()) +
                                                          " joint names for " + std::to_string(n) + " limits");
  const std::vector<Eigen::VectorXd> waypoints = distinctWaypoints(path, n);
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = joint_names;
  if (waypoints.size() == 1)
  {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    appendPoint(trajectory, 0.0, waypoints.front(), zero, zero);
    return trajectory;
  }
  const std::vector<PathPiece> pieces = blendedPath(waypoints, options_.max_deviation);
  const std::vector<Interval> intervals = pathGrid(pieces, options_.path_step);
  const GridDerivatives derivatives = gridDerivatives(pieces, intervals, n);
  const PhasePlane plane(options_.max_velocity, options_.max_acceleration, options_.safety);
  const PhasePlane true_plane(options_.max_velocity, options_.max_acceleration, 1.0);
  const std::vector<double> x = squaredPathVelocity(intervals, derivatives, plane, true_plane,
                                                    velocityLimitCurve(derivatives, plane));
  const std::vector<double> times = gridTimes(intervals, x);
  checkDuration(times.back(), options_);
  sampleMotion(pieces, intervals, x, times, options_.sample_period, waypoints.back(), trajectory);
  return trajectory;
}
}  // namespace vrrw_kinematics
