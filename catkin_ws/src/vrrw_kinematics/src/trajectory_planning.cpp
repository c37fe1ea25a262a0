#include <vrrw_kinematics/trajectory_planning.h>

#include <vrrw_kinematics/kinematics_error.h>

#include <chrono>
#include <cmath>

namespace vrrw_kinematics
{
namespace
{
using Clock = std::chrono::steady_clock;
/// A leg gets at least this much planning time (s); less is reported as the time limit running out.
constexpr double kMinLegTime = 1e-3;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool fail(TrajectoryResult& result, ErrorCode code, const std::string& message, int waypoint,
          const Contact& contact = {})
{
  result.success = false;
  result.code = code;
  result.message = message;
  result.failed_waypoint = waypoint;
  result.contact = contact;
  result.trajectory.points.clear();
  result.waypoint_times.clear();
  result.path.clear();
  return false;
}

/// The blended timing unless it cuts a corner into an obstacle; then the one that stays on the polyline.
vrrw_trajectory::JointTrajectory timedLeg(MotionPlanner& planner, const TimeParameterization& blended,
                                          const TimeParameterization& exact, const std::vector<Eigen::VectorXd>& path)
{
  vrrw_trajectory::JointTrajectory leg = blended.compute(path, planner.jointNames());
  if (!planner.trajectoryValid(leg))
    leg = exact.compute(path, planner.jointNames());
  return leg;
}

/// The limits times the request's scaling; empty limits (and `result` failed) when a factor is not in (0, 1].
TimingOptions scaled(const TimingOptions& limits, const SpeedScaling& scaling, TrajectoryResult& result)
{
  for (const auto& [name, factor] : { std::pair{ "max_velocity_scaling_factor", scaling.velocity },
                                      std::pair{ "max_acceleration_scaling_factor", scaling.acceleration } })
    if (!(factor > 0.0 && factor <= 1.0))
    {
      fail(result, ErrorCode::InvalidArgument, std::string(name) + ": " + std::to_string(factor) + ": must be in (0, 1]", -1);
      return {};
    }
  TimingOptions timing = limits;
  for (double& v : timing.max_velocity)
    v *= scaling.velocity;
  for (double& a : timing.max_acceleration)
    a *= scaling.acceleration;
  return timing;
}

bool endpointsValid(MotionPlanner& planner, const TrajectoryRequest& request, TrajectoryResult& result)
{
  const PlanResult start = planner.checkEndpoint(request.plan.start, "start");
  if (!start.success)
    return fail(result, start.code, start.message, -1, start.contact);
  for (std::size_t i = 0; i < request.waypoints.size(); ++i)
  {
    const PlanResult waypoint = planner.checkEndpoint(request.waypoints[i], "waypoint " + std::to_string(i));
    if (!waypoint.success)
      return fail(result, waypoint.code, waypoint.message, static_cast<int>(i), waypoint.contact);
  }
  return true;
}
}  // namespace

void appendTrajectory(TrajectoryResult& result, const TrajectoryResult& next)
{
  const bool first = result.trajectory.points.empty();
  const double offset = first ? 0.0 : result.trajectory.points.back().time;
  result.trajectory.joint_names = next.trajectory.joint_names;
  for (std::size_t k = first ? 0 : 1; k < next.trajectory.points.size(); ++k)
  {
    result.trajectory.points.push_back(next.trajectory.points[k]);
    result.trajectory.points.back().time += offset;
  }
  for (const double t : next.waypoint_times)
    result.waypoint_times.push_back(t + offset);
  const bool joined = !result.path.empty() && !next.path.empty();
  result.path.insert(result.path.end(), next.path.begin() + (joined ? 1 : 0), next.path.end());
  result.planning_time += next.planning_time;
  result.path_length += next.path_length;
}

SpeedScaling speedScaling(double max_velocity_scaling_factor, double max_acceleration_scaling_factor)
{
  return { max_velocity_scaling_factor == 0.0 ? 1.0 : max_velocity_scaling_factor,
           max_acceleration_scaling_factor == 0.0 ? 1.0 : max_acceleration_scaling_factor };
}

TrajectoryResult planTrajectory(MotionPlanner& planner, const TimingOptions& limits, const TrajectoryRequest& request)
{
  const Clock::time_point started = Clock::now();
  TrajectoryResult result;
  const double limit = request.plan.time_limit;
  if (!std::isfinite(limit) || limit <= 0.0)
  {
    fail(result, ErrorCode::InvalidArgument, "time limit: must be positive and finite, got " + std::to_string(limit), -1);
    return result;
  }
  const TimingOptions timing = scaled(limits, request.scaling, result);
  if (timing.max_velocity.empty() || !endpointsValid(planner, request, result))
    return result;
  const TimeParameterization blended(timing);
  TimingOptions stopping = timing;
  stopping.max_deviation = 0.0;
  const TimeParameterization exact(stopping);
  const std::size_t legs = request.waypoints.size() + 1;
  Eigen::VectorXd from = request.plan.start;
  for (std::size_t leg = 0; leg < legs; ++leg)
  {
    const bool to_goal = leg + 1 == legs;
    const std::string label = to_goal ? (legs > 1 ? "to the goal: " : "") : "waypoint " + std::to_string(leg) + ": ";
    PlanRequest step = request.plan;
    step.start = from;
    step.seed = request.plan.seed + leg;
    step.time_limit = limit - secondsSince(started);
    if (!to_goal)
    {
      step.goal_joints = request.waypoints[leg];
      step.goal_pose.reset();
    }
    if (step.time_limit < kMinLegTime)
    {
      fail(result, ErrorCode::PlanningFailed, label + "no time left of the " + std::to_string(limit) + " s limit",
           static_cast<int>(leg));
      return result;
    }
    const PlanResult planned = planner.plan(step);
    result.planning_time += planned.planning_time;
    if (!planned.success)
    {
      fail(result, planned.code, label + planned.message, static_cast<int>(leg), planned.contact);
      return result;
    }
    TrajectoryResult timed;
    try
    {
      timed.trajectory = request.profile == TimeProfile::MinimumJerk
                           ? minimumJerkTrajectory(planned.path, planner.jointNames(), timing)
                           : timedLeg(planner, blended, exact, planned.path);
      checkDuration(result.trajectory.duration() + timed.trajectory.duration(), timing);  // the plan as a whole
    }
    catch (const KinematicsError& e)  // too long: a request as a whole
    {
      fail(result, e.code(), e.what(), -1);
      return result;
    }
    timed.waypoint_times = { timed.trajectory.points.back().time };
    timed.path = planned.path;
    timed.path_length = pathLength(planned.path);
    appendTrajectory(result, timed);
    from = planned.path.back();
  }
  result.success = true;
  result.code = ErrorCode::Ok;
  return result;
}
}  // namespace vrrw_kinematics
