#include <algorithm>
#include <cmath>
#include <sstream>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_control/splice_segment.h>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_control/trajectory_validator.h>

namespace vrrw_control
{
namespace
{
bool reject(Validation& v, Validation::Error error, int point, const std::string& joint, const std::string& reason)
{
  v.error = error;
  v.point = point;
  v.joint = joint;
  std::ostringstream s;
  if (point >= 0)
    s << "point " << point << ": ";
  if (!joint.empty())
    s << "joint " << joint << ": ";
  s << reason;
  v.message = s.str();
  return false;
}

std::string fmt(double x)
{
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

/// The joint whose value differs most between \a a and \a b.
size_t farthestJoint(const std::vector<double>& a, const std::vector<double>& b)
{
  size_t worst = 0;
  for (size_t j = 1; j < a.size(); ++j)
    if (std::abs(a[j] - b[j]) > std::abs(a[worst] - b[worst]))
      worst = j;
  return worst;
}

vrrw_trajectory::TrajectoryPoint restAt(const std::vector<double>& positions)
{
  vrrw_trajectory::TrajectoryPoint rest;
  rest.positions = positions;
  rest.velocities.assign(positions.size(), 0.0);
  rest.accelerations.assign(positions.size(), 0.0);
  return rest;
}

bool allFinite(const std::vector<double>& values, size_t& bad)
{
  for (bad = 0; bad < values.size(); ++bad)
    if (!std::isfinite(values[bad]))
      return false;
  return true;
}
}  // namespace

TrajectoryValidator::TrajectoryValidator(std::vector<JointLimits> limits, ValidationOptions options)
  : limits_(std::move(limits)), options_(options)
{
}

bool TrajectoryValidator::checkJoints(const vrrw_trajectory::JointTrajectory& goal, Validation& v,
                                      std::vector<size_t>& order) const
{
  std::vector<std::string> robot;
  for (const auto& joint : limits_)
    robot.push_back(joint.name);
  try
  {
    order = vrrw_common::jointMapping(goal.joint_names, robot, vrrw_common::OtherJoints::Refuse);
    return true;
  }
  catch (const vrrw_common::JointMappingError& e)
  {
    const std::string reason = e.reason() == "named twice" ? "named twice in joint_names" :
                               e.reason() == "missing"     ? "missing from joint_names" :
                                                             "not a joint of this controller";
    return reject(v, Validation::Error::InvalidJoints, -1, e.joint(), reason);
  }
}

bool TrajectoryValidator::checkPoints(const vrrw_trajectory::JointTrajectory& goal, const std::vector<size_t>& order,
                                      Validation& v) const
{
  const auto Bad = Validation::Error::InvalidGoal;
  const size_t n = limits_.size();
  if (goal.points.empty())
    return reject(v, Bad, -1, "", "trajectory has no points");
  for (size_t i = 0; i < goal.points.size(); ++i)
  {
    const auto& p = goal.points[i];
    const int pi = static_cast<int>(i);
    if (p.positions.size() != n)
      return reject(v, Bad, pi, "", "positions has " + std::to_string(p.positions.size()) + " values, expected " +
                                        std::to_string(n));
    if (!p.velocities.empty() && p.velocities.size() != n)
      return reject(v, Bad, pi, "",
                    "velocities has " + std::to_string(p.velocities.size()) + " values, expected 0 or " +
                        std::to_string(n));
    if (!p.accelerations.empty() && p.accelerations.size() != n)
      return reject(v, Bad, pi, "",
                    "accelerations has " + std::to_string(p.accelerations.size()) + " values, expected 0 or " +
                        std::to_string(n));
    if (!std::isfinite(p.time))
      return reject(v, Bad, pi, "", "time_from_start is not finite");
    if (i == 0 && p.time < 0.0)
      return reject(v, Bad, pi, "", "time_from_start " + fmt(p.time) + " s is negative");
    if (i > 0 && !(p.time > goal.points[i - 1].time))
      return reject(v, Bad, pi, "",
                    "time_from_start " + fmt(p.time) + " s does not increase (previous point " +
                        fmt(goal.points[i - 1].time) + " s)");
    size_t bad = 0;
    for (const auto* values : { &p.positions, &p.velocities, &p.accelerations })
      if (!allFinite(*values, bad))
        return reject(v, Bad, pi, goal.joint_names[bad], "value is not finite");
    for (size_t j = 0; j < n; ++j)
    {
      const auto& l = limits_[j];
      const size_t k = order[j];
      const double q = p.positions[k];
      if (l.has_position_limits && (q < l.min_position || q > l.max_position))
        return reject(v, Bad, pi, l.name,
                      "position " + fmt(q) + " outside limits [" + fmt(l.min_position) + ", " +
                          fmt(l.max_position) + "]");
      if (!p.velocities.empty() && std::abs(p.velocities[k]) > l.max_velocity)
        return reject(v, Bad, pi, l.name,
                      "velocity " + fmt(p.velocities[k]) + " exceeds limit " + fmt(l.max_velocity));
      if (!p.accelerations.empty() && std::abs(p.accelerations[k]) > l.max_acceleration)
        return reject(v, Bad, pi, l.name,
                      "acceleration " + fmt(p.accelerations[k]) + " exceeds limit " + fmt(l.max_acceleration));
    }
  }
  return true;
}

// Points within the limits can still be joined by a spline that leaves them: the interpolant is sampled between
// every two points (samples_per_segment) against the position limits and, with a slack, the velocity limits.
// Rejections name the goal's own point (index_shift maps back from the executable's, which may have one
// prepended).
bool TrajectoryValidator::checkInterpolant(int index_shift, Validation& v) const
{
  const auto& traj = v.executable;
  const TrajectoryInterpolator interp(traj);
  const double slack = 1.0 + options_.interpolant_slack;
  for (size_t i = 1; i < traj.points.size(); ++i)
  {
    const double t0 = traj.points[i - 1].time, t1 = traj.points[i].time;
    const int goal_point = static_cast<int>(i) - index_shift;
    for (int s = 1; s < options_.samples_per_segment; ++s)
    {
      const JointSample x = interp.sample(t0 + (t1 - t0) * s / options_.samples_per_segment);
      for (size_t j = 0; j < limits_.size(); ++j)
      {
        const auto& l = limits_[j];
        const double q = x.positions[j];
        if (l.has_position_limits && (q < l.min_position || q > l.max_position))
          return reject(v, Validation::Error::InvalidGoal, goal_point, l.name,
                        "interpolated position " + fmt(q) + " before this point leaves limits [" +
                            fmt(l.min_position) + ", " + fmt(l.max_position) + "]");
        // without velocities at both ends the interpolator moves linearly: its velocity is the chord's
        const bool linear = traj.points[i].velocities.empty() || traj.points[i - 1].velocities.empty();
        const double qd =
            linear ? (traj.points[i].positions[j] - traj.points[i - 1].positions[j]) / (t1 - t0) : x.velocities[j];
        if (std::abs(qd) > slack * l.max_velocity)
          return reject(v, Validation::Error::InvalidGoal, goal_point, l.name,
                        "interpolated velocity " + fmt(qd) + " before this point exceeds limit " +
                            fmt(l.max_velocity));
      }
    }
  }
  return true;
}

bool TrajectoryValidator::checkAndReorder(const vrrw_trajectory::JointTrajectory& goal, Validation& v) const
{
  std::vector<size_t> order;
  if (!checkJoints(goal, v, order) || !checkPoints(goal, order, v))
    return false;
  auto& out = v.executable;
  for (const auto& l : limits_)
    out.joint_names.push_back(l.name);
  for (const auto& p : goal.points)
  {
    vrrw_trajectory::TrajectoryPoint q;
    q.time = p.time;
    for (size_t j = 0; j < limits_.size(); ++j)
    {
      q.positions.push_back(p.positions[order[j]]);
      if (!p.velocities.empty())
        q.velocities.push_back(p.velocities[order[j]]);
      if (!p.accelerations.empty())
        q.accelerations.push_back(p.accelerations[order[j]]);
    }
    out.points.push_back(q);
  }
  return true;
}

Validation TrajectoryValidator::validate(const vrrw_trajectory::JointTrajectory& goal, const JointSample& current) const
{
  Validation v;
  if (!checkAndReorder(goal, v))
    return v;
  auto& out = v.executable;
  const size_t worst = farthestJoint(out.points.front().positions, current.positions);
  const double worst_error = std::abs(out.points.front().positions[worst] - current.positions[worst]);
  if (worst_error > options_.start_tolerance)
  {
    reject(v, Validation::Error::InvalidGoal, 0, limits_[worst].name,
           "starts " + fmt(worst_error) + " from the current position " + fmt(current.positions[worst]) +
               " (start tolerance " + fmt(options_.start_tolerance) + ")");
    return v;
  }
  // a first point later than 0 is reached from the current state at rest, as joint_trajectory_controller does
  const bool prepend = out.points.front().time > 0.0;
  if (prepend)
    out.points.insert(out.points.begin(), restAt(current.positions));
  checkInterpolant(prepend ? 1 : 0, v);
  return v;
}

// Which of a new goal's points the running motion has not passed yet at `elapsed` (time since the goal's
// start): those before it are dropped and the splice segment leads into the first kept one. A resting arm that
// the goal does not start at keeps every point (the splice is the whole approach).
size_t TrajectoryValidator::firstKeptPoint(const std::vector<vrrw_trajectory::TrajectoryPoint>& points,
                                           const JointSample& current, double elapsed, bool& own_segment) const
{
  const bool at_rest =
      std::all_of(current.velocities.begin(), current.velocities.end(), [](double qd) { return qd == 0.0; });
  const auto& first = points.front().positions;
  const size_t worst = farthestJoint(first, current.positions);
  const bool starts_here = std::abs(first[worst] - current.positions[worst]) <= options_.start_tolerance;
  own_segment = false;
  if (at_rest && !starts_here)
    return 0;
  size_t kept = 0;
  while (kept + 1 < points.size() && points[kept].time <= elapsed)
    ++kept;
  // a goal that starts where the resting arm is keeps the timing of its own first segment
  own_segment = at_rest && kept == 1 && points[0].time <= elapsed && points[1].time > elapsed;
  return kept;
}

// Stages: check and reorder the goal; drop the points already passed; time the splice segment from the
// current state into the first kept point (its own timing, or the shortest that keeps the limits); shift the
// rest of the goal by the same amount; check the whole interpolant.
Validation TrajectoryValidator::splice(const vrrw_trajectory::JointTrajectory& goal, const JointSample& current,
                                       double elapsed) const
{
  Validation v;
  if (!checkAndReorder(goal, v))
    return v;
  auto& points = v.executable.points;
  bool own_segment = false;
  const size_t first = firstKeptPoint(points, current, elapsed, own_segment);
  points.erase(points.begin(), points.begin() + static_cast<long>(first));

  // the splice segment ends in the first kept point (splice_segment.h); a point of positions only is
  // reached at rest, by a quintic, rather than by a line with a velocity step
  auto& target = points.front();
  if (target.velocities.empty())
  {
    target.velocities.assign(limits_.size(), 0.0);
    target.accelerations.assign(limits_.size(), 0.0);
  }
  const auto order = target.accelerations.empty() ? SplineSegment::Order::Cubic : SplineSegment::Order::Quintic;
  JointSample end(limits_.size());
  end.positions = target.positions;
  end.velocities = target.velocities;
  if (!target.accelerations.empty())
    end.accelerations = target.accelerations;
  const double own = std::max(target.time - elapsed, kShortestSplice);
  const double duration = own_segment ? own : shortestSplice(order, current, end, own, limits_);
  if (!std::isfinite(duration))
  {
    const SpliceCheck why = checkSplice(order, current, end, kLongestSplice, limits_);
    reject(v, Validation::Error::InvalidGoal, static_cast<int>(first), why.joint,
           "cannot be joined from the current state within the limits: " + why.reason);
    return v;
  }
  v.blended = duration > own;
  const double shift = duration - target.time;  // the first kept point lands at the end of the splice
  for (auto& p : points)
    p.time += shift;
  vrrw_trajectory::TrajectoryPoint from;
  from.positions = current.positions;
  from.velocities = current.velocities;
  from.accelerations = current.accelerations;
  points.insert(points.begin(), from);
  checkInterpolant(1 - static_cast<int>(first), v);
  return v;
}
}  // namespace vrrw_control
