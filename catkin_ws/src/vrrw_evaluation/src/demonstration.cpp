#include <vrrw_evaluation/demonstration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vrrw_evaluation
{
using vrrw_trajectory::JointTrajectory;
using vrrw_trajectory::TrajectoryPoint;

const Segment& Demonstration::segment(const std::string& name) const
{
  for (const Segment& s : segments)
    if (s.name == name)
      return s;
  throw std::invalid_argument("the demonstration has no segment '" + name + "'");
}

std::vector<double> positionsAt(const JointTrajectory& trajectory, double t)
{
  const auto& points = trajectory.points;
  if (points.empty())
    throw std::invalid_argument("positionsAt: empty trajectory");
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

JointTrajectory slice(const JointTrajectory& trajectory, double start, double end)
{
  JointTrajectory out;
  out.joint_names = trajectory.joint_names;
  out.points.push_back({ 0.0, positionsAt(trajectory, start), {}, {} });
  for (const TrajectoryPoint& p : trajectory.points)
    if (p.time > start + kEndGap && p.time < end - kEndGap)
      out.points.push_back({ p.time - start, p.positions, p.velocities, {} });
  out.points.push_back({ end - start, positionsAt(trajectory, end), {}, {} });
  if (end - start <= 0.0 || out.points.size() < 3)
    throw std::invalid_argument("slice [" + std::to_string(start) + ", " + std::to_string(end) +
                                "] s holds fewer than 3 samples");
  return out;
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
    throw std::invalid_argument("jointRms: empty trajectory");
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
}  // namespace vrrw_evaluation
