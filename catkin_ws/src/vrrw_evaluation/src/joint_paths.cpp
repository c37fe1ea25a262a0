#include <vrrw_evaluation/joint_paths.h>
#include <vrrw_evaluation/evaluation_error.h>

#include <algorithm>
#include <cmath>

#include <vrrw_demos/segmentation.h>

namespace vrrw_evaluation
{
using vrrw_trajectory::JointTrajectory;
using vrrw_trajectory::TrajectoryPoint;

std::vector<double> positionsAt(const JointTrajectory& trajectory, double t)
{
  const auto& points = trajectory.points;
  if (points.empty())
    throw EvaluationError("positionsAt: empty trajectory");
  if (t <= points.front().time)
    return points.front().positions;
  if (t >= points.back().time)
    return points.back().positions;
  const auto after = std::upper_bound(points.begin(), points.end(), t,
                                      [](double time, const TrajectoryPoint& p) { return time < p.time; });
  const TrajectoryPoint& b = *after;
  const TrajectoryPoint& a = *(after - 1);
  const double s = b.time > a.time ? (t - a.time) / (b.time - a.time) : 1.0;
  std::vector<double> q(a.positions.size());
  for (std::size_t j = 0; j < q.size(); ++j)
    q[j] = a.positions[j] + s * (b.positions[j] - a.positions[j]);
  return q;
}

double largestJointDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double largest = 0.0;
  for (std::size_t j = 0; j < a.size() && j < b.size(); ++j)
    largest = std::max(largest, std::abs(a[j] - b[j]));
  return largest;
}

double jointRms(const JointTrajectory& reference, const JointTrajectory& measured)
{
  if (reference.points.empty() || measured.points.empty())
    throw EvaluationError("jointRms: empty trajectory");
  const double t0 = reference.points.front().time;
  const double m0 = measured.points.front().time;
  double sum = 0.0;
  std::size_t count = 0;
  for (const TrajectoryPoint& p : reference.points)
  {
    const std::vector<double> q = positionsAt(measured, m0 + p.time - t0);
    for (std::size_t j = 0; j < q.size() && j < p.positions.size(); ++j, ++count)
      sum += (q[j] - p.positions[j]) * (q[j] - p.positions[j]);
  }
  return std::sqrt(sum / double(std::max<std::size_t>(count, 1)));
}

JointTrajectory thin(const JointTrajectory& trajectory, double period)
{
  JointTrajectory out;
  out.joint_names = trajectory.joint_names;
  for (const TrajectoryPoint& p : trajectory.points)
    if (out.points.empty() || p.time - out.points.back().time >= period - 1e-9)
      out.points.push_back(p);
  if (!trajectory.points.empty() && out.points.back().time < trajectory.points.back().time)
    out.points.push_back(trajectory.points.back());
  return out;
}

void addVelocities(JointTrajectory& trajectory)
{
  auto& p = trajectory.points;
  for (std::size_t k = 0; k < p.size(); ++k)
  {
    p[k].velocities.assign(p[k].positions.size(), 0.0);
    if (k == 0 || k + 1 == p.size())
      continue;
    for (std::size_t j = 0; j < p[k].positions.size(); ++j)
      p[k].velocities[j] = (p[k + 1].positions[j] - p[k - 1].positions[j]) / (p[k + 1].time - p[k - 1].time);
  }
}
vrrw_demos::RobotTrack asTrack(JointTrajectory trajectory, const std::string& robot)
{
  addVelocities(trajectory);
  vrrw_demos::RobotTrack track;
  track.robot = robot;
  track.joint_names = trajectory.joint_names;
  for (const TrajectoryPoint& p : trajectory.points)
    track.states.push_back({ p.time, p.positions, p.velocities, 0.0 });
  return track;
}

JointTrajectory instructionGoal(const vrrw_demos::RobotTrack& track, double start, double end)
{
  // s: recorded states this close to an end are left out (the interpolated end stands for them), so the goal has
  // no near-zero interval (a stamp 0.1 ms after the start would ask for any speed)
  constexpr double kEndGap = 0.005;
  JointTrajectory goal;
  goal.joint_names = track.joint_names;
  const auto states = vrrw_demos::slice(track, start, end).states;
  for (std::size_t k = 0; k < states.size(); ++k)
    if (k == 0 || k + 1 == states.size() || (states[k].time > start + kEndGap && states[k].time < end - kEndGap))
      goal.points.push_back({ states[k].time - start, states[k].positions, {}, {} });
  addVelocities(goal);
  return goal;
}
}  // namespace vrrw_evaluation
