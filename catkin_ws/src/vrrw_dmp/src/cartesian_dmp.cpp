#include <vrrw_dmp/cartesian_dmp.h>

#include <algorithm>
#include <cmath>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/quaternion_maps.h>

#include "format_number.h"

namespace vrrw_dmp
{
namespace
{
std::vector<double> asVector(const Eigen::Vector3d& v)
{
  return { v.x(), v.y(), v.z() };
}

Eigen::Vector3d asEigen(const std::vector<double>& v)
{
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

void checkPosition(const Eigen::Vector3d& p, const std::string& what)
{
  if (!p.allFinite())
    throw DmpError(what + ": position is not finite");
}

/// ceil(tau / dt) of a valid request; throws DmpError naming what is wrong or over the limit.
std::size_t nominalSteps(double tau, double dt)
{
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw DmpError("dt = " + format(dt) + ": must be a finite number > 0");
  if (!(tau > 0.0) || !std::isfinite(tau))
    throw DmpError("tau = " + format(tau) + ": must be a finite number > 0");
  if (dt > tau)
    throw DmpError("dt = " + format(dt) + " is longer than tau = " + format(tau));
  const double steps = std::ceil(tau / dt - 1e-9);
  if (Dmp::kSettlingFactor * steps + 1.0 > static_cast<double>(Dmp::kMaxRolloutSamples))
    throw DmpError("tau = " + format(tau) + " s at dt = " + format(dt) + " s needs up to " +
                   format(Dmp::kSettlingFactor * steps + 1.0) + " samples, more than the limit of " +
                   std::to_string(Dmp::kMaxRolloutSamples) + ": raise dt or shorten tau");
  return static_cast<std::size_t>(steps);
}
}  // namespace

CartesianDmp CartesianDmp::learn(const std::vector<CartesianSample>& demo, const DmpParameters& parameters,
                                 const DmpProvenance& provenance)
{
  vrrw_trajectory::JointTrajectory positions;
  positions.joint_names = { "x", "y", "z" };
  std::vector<double> times;
  std::vector<Eigen::Quaterniond> orientations;
  for (std::size_t k = 0; k < demo.size(); ++k)
  {
    checkPosition(demo[k].pose.position, "Cartesian demo: sample " + std::to_string(k));
    positions.points.push_back({ demo[k].time, asVector(demo[k].pose.position), {}, {} });
    times.push_back(demo[k].time);
    orientations.push_back(demo[k].pose.orientation);
  }
  return CartesianDmp(Dmp::learn(positions, parameters, provenance),
                      OrientationDmp::learn(times, orientations, parameters));
}

CartesianDmp::CartesianDmp(Dmp position, OrientationDmp orientation)
  : position_(std::move(position)), orientation_(std::move(orientation))
{
  if (position_.dofs() != 3)
    throw DmpError("Cartesian model: the position DMP has " + std::to_string(position_.dofs()) + " axes, not 3");
  if (position_.basis().centers() != orientation_.basis().centers() ||
      position_.demoDuration() != orientation_.demoDuration() ||
      position_.parameters().alpha != orientation_.parameters().alpha)
    throw DmpError("Cartesian model: position and orientation differ in basis, alpha or duration");
}

CartesianPose CartesianDmp::demoStart() const
{
  return { asEigen(position_.demoStart()), orientation_.demoStart() };
}

CartesianPose CartesianDmp::demoGoal() const
{
  return { asEigen(position_.demoGoal()), orientation_.demoGoal() };
}

std::vector<std::string> CartesianDmp::warnings() const
{
  std::vector<std::string> all = position_.warnings();
  all.insert(all.end(), orientation_.warnings().begin(), orientation_.warnings().end());
  return all;
}

std::vector<CartesianSample> CartesianDmp::rollout(const CartesianRolloutRequest& request) const
{
  const double tau = request.tau > 0.0 ? request.tau : demoDuration();
  if (request.tau < 0.0 || !std::isfinite(request.tau))
    throw DmpError("tau = " + format(request.tau) + ": must be a finite number > 0");
  const std::size_t nominal = nominalSteps(tau, request.dt);
  const CartesianPose start = request.start.value_or(demoStart());
  const CartesianPose goal = request.goal.value_or(demoGoal());
  checkPosition(start.position, "start");
  checkPosition(goal.position, "goal");
  DmpState position = position_.begin(asVector(start.position), asVector(goal.position), tau);
  OrientationState orientation = orientation_.begin(start.orientation, goal.orientation, tau);
  std::vector<CartesianSample> out;
  out.reserve(nominal + nominal / 4 + 1);
  const std::size_t last = Dmp::kSettlingFactor * nominal;
  for (std::size_t k = 0;; ++k)
  {
    CartesianSample sample;
    sample.time = static_cast<double>(k) * request.dt;
    sample.pose.position = asEigen(position.positions);
    sample.pose.orientation = orientation.orientation;
    sample.velocity = asEigen(position.velocities);
    sample.angular_velocity = orientation.angular_velocity;
    out.push_back(sample);
    if (k >= last)
      break;
    if (k >= nominal && (sample.pose.position - goal.position).norm() <= request.position_tolerance &&
        angleBetween(sample.pose.orientation, orientation.goal) <= request.angle_tolerance &&
        sample.velocity.norm() <= request.rest_speed && sample.angular_velocity.norm() <= request.rest_angular_speed)
      break;
    position_.step(position, request.dt);
    orientation_.step(orientation, request.dt);
  }
  return out;
}

CartesianPose poseAt(const std::vector<CartesianSample>& path, double t)
{
  if (path.empty())
    throw DmpError("poseAt: empty path");
  if (t <= path.front().time)
    return path.front().pose;
  if (t >= path.back().time)
    return path.back().pose;
  const auto after = std::upper_bound(path.begin(), path.end(), t,
                                      [](double time, const CartesianSample& s) { return time < s.time; });
  const CartesianSample& b = *after;
  const CartesianSample& a = *(after - 1);
  const double u = (t - a.time) / (b.time - a.time);
  CartesianPose pose;
  pose.position = a.pose.position + u * (b.pose.position - a.pose.position);
  pose.orientation = a.pose.orientation.slerp(u, b.pose.orientation);
  return pose;
}

CartesianFit reproductionError(const CartesianDmp& dmp, const std::vector<CartesianSample>& demo)
{
  CartesianRolloutRequest request;
  request.dt = std::min(0.002, dmp.demoDuration() / 100.0);
  const auto rollout = dmp.rollout(request);
  double position = 0.0, angle = 0.0;
  for (const CartesianSample& sample : demo)
  {
    const CartesianPose reproduced = poseAt(rollout, sample.time - demo.front().time);
    position += (reproduced.position - sample.pose.position).squaredNorm();
    angle += std::pow(angleBetween(reproduced.orientation, sample.pose.orientation), 2);
  }
  const double n = static_cast<double>(std::max<std::size_t>(demo.size(), 1));
  return { std::sqrt(position / n), std::sqrt(angle / n) };
}
}  // namespace vrrw_dmp
