#include "vrrw_kinematics/motion_planner.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/goals/GoalStates.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/planner_factory.h"
#include "ompl_state.h"
#include "resolution_motion_validator.h"
#include "seeded_state_sampler.h"

namespace vrrw_kinematics
{
namespace
{
namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;
/// Longest tree edge (joint-space distance) of the first attempt for planners with a range: measured best
/// for the UR5e in pick_place_drill (p95 plan time 14-17 ms at 2-3 rad against 25 ms at OMPL's ~6 rad).
constexpr double kRange = 2.5;
constexpr int kShortcutFailures = 5;
/// First planner attempt (s); each restart doubles it. Most queries take under 30 ms.
constexpr double kFirstAttempt = 0.1;
constexpr double kMinRange = 0.3;

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}
}  // namespace

MotionPlanner::MotionPlanner(const CollisionWorld& world, const std::vector<std::string>& joints,
                             const std::string& tip_link, const Eigen::VectorXd& world_state, double resolution)
  : checker_(world, joints, world_state), bounds_(world.model(), joints), segments_(checker_, resolution)
{
  const RobotModel& model = world.model();

  const std::string base = model.links()[model.joints()[model.jointIndex(joints.front())].parent_link].name;
  const KinematicChain chain(model, base, tip_link);
  if (chain.jointNames() != joints)
    throw KinematicsError(ErrorCode::NotSerialChain, "chain " + base + " -> " + tip_link +
                                                         ": its movable joints are not exactly the planning group");
  ik_ = std::make_unique<IkSolver>(chain);
  chain_base_pose_ = model.relativeTransform(world_state, model.links()[0].name, base);

  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  space_ = std::make_shared<ob::RealVectorStateSpace>(joints.size());
  auto& space = space_;
  ob::RealVectorBounds bounds(joints.size());
  for (std::size_t i = 0; i < joints.size(); ++i)
  {
    bounds.setLow(i, bounds_.lower()[static_cast<Eigen::Index>(i)]);
    bounds.setHigh(i, bounds_.upper()[static_cast<Eigen::Index>(i)]);
  }
  space->setBounds(bounds);
  space->setStateSamplerAllocator(
      [this](const ob::StateSpace* s) { return std::make_shared<SeededStateSampler>(s, sampler_seed_++); });
  si_ = std::make_shared<ob::SpaceInformation>(space);
  const std::size_t n = joints.size();
  si_->setStateValidityChecker([this, n](const ob::State* state) { return checker_.valid(toEigen(state, n)); });
  si_->setMotionValidator(std::make_shared<ResolutionMotionValidator>(si_, segments_));
  si_->setup();
}

MotionPlanner::~MotionPlanner() = default;

bool MotionPlanner::stateValid(const Eigen::VectorXd& q)
{
  return bounds_.violation(q).empty() && checker_.valid(q);
}

bool MotionPlanner::pathValid(const std::vector<Eigen::VectorXd>& path)
{
  if (path.empty() || !stateValid(path.front()))
    return false;
  for (std::size_t i = 1; i < path.size(); ++i)
    if (!bounds_.violation(path[i]).empty() || !segments_.valid(path[i - 1], path[i]))
      return false;
  return true;
}

bool MotionPlanner::trajectoryValid(const vrrw_trajectory::JointTrajectory& trajectory)
{
  std::vector<Eigen::VectorXd> path;
  for (const auto& point : trajectory.points)
    path.push_back(Eigen::Map<const Eigen::VectorXd>(point.positions.data(),
                                                     static_cast<Eigen::Index>(point.positions.size())));
  return pathValid(path);
}

PlanResult MotionPlanner::fail(ErrorCode code, const std::string& message, const Contact& contact) const
{
  PlanResult result;
  result.code = code;
  result.message = message;
  result.contact = contact;
  return result;
}

PlanResult MotionPlanner::checkEndpoint(const Eigen::VectorXd& q, const std::string& label)
{
  if (static_cast<std::size_t>(q.size()) != size())
    return fail(ErrorCode::InvalidArgument, label + ": expected " + std::to_string(size()) + " joint values, got " +
                                                std::to_string(q.size()));
  const std::string violation = bounds_.violation(q);
  if (!violation.empty())
    return fail(ErrorCode::OutsideLimits, label + ": " + violation);
  const Contact contact = checker_.check(q);
  if (contact.collision)
    return fail(ErrorCode::InCollision, label + ": in collision (" + contact.body_a + " - " + contact.body_b + ")",
                contact);
  PlanResult valid;
  valid.success = true;
  valid.code = ErrorCode::Ok;
  return valid;
}

bool MotionPlanner::goalStates(const PlanRequest& request, double budget, std::vector<Eigen::VectorXd>& goals,
                               PlanResult& error)
{
  if (request.goal_joints)
  {
    error = checkEndpoint(*request.goal_joints, "goal");
    if (!error.success)
      return false;
    goals.push_back(bounds_.nearestTurn(*request.goal_joints, request.start));
    return true;
  }
  if (!request.goal_pose)
  {
    error = fail(ErrorCode::InvalidArgument, "goal: neither joint values nor a pose");
    return false;
  }
  const std::string reason = invalidPoseReason(*request.goal_pose);
  if (!reason.empty())
  {
    error = fail(ErrorCode::InvalidPose, "goal pose: " + reason);
    return false;
  }
  const Eigen::Isometry3d target = chain_base_pose_.inverse() * *request.goal_pose;
  const Clock::time_point start = Clock::now();
  Contact first_contact;
  bool any_solution = false;
  std::vector<Eigen::VectorXd> candidates = ik_->solveAll(target, request.start);
  IkOptions options = request.ik;
  options.seed = request.seed;
  Eigen::VectorXd seed = request.start;
  std::mt19937_64 rng(request.seed);
  while (goals.size() < 4 && seconds(start) < budget)
  {
    if (candidates.empty())
    {
      options.timeout = std::max(0.0, std::min(options.timeout, budget - seconds(start)));
      const IkResult result = ik_->solve(target, seed, options);
      ++options.seed;
      seed = ik_->chain().randomState(rng);
      if (!result.success)
      {
        if (ik_->hasAnalytic())
          break;
        continue;
      }
      candidates.push_back(result.q);
    }
    for (const Eigen::VectorXd& q : candidates)
    {
      any_solution = true;
      const Contact contact = checker_.check(q);
      if (!contact.collision)
        goals.push_back(bounds_.nearestTurn(q, request.start));
      else if (!first_contact.collision)
        first_contact = contact;
    }
    candidates.clear();
    if (ik_->hasAnalytic() && request.ik.mode == IkOptions::Mode::Full)
      break;
  }
  if (!goals.empty())
  {
    std::sort(goals.begin(), goals.end(), [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return (a - request.start).squaredNorm() < (b - request.start).squaredNorm();
    });
    return true;
  }
  if (!any_solution)
    error = fail(ErrorCode::NoSolution, "goal pose: unreachable for " + ik_->chain().tipLink() + " (no IK solution)");
  else
    error = fail(ErrorCode::InCollision, "goal pose: every IK solution is in collision (" + first_contact.body_a +
                                             " - " + first_contact.body_b + ")",
                 first_contact);
  return false;
}

PlanResult MotionPlanner::plan(const PlanRequest& request)
{
  const Clock::time_point start_time = Clock::now();
  const PlanResult start_problem = checkEndpoint(request.start, "start");
  if (!start_problem.success)
    return start_problem;
  if (!std::isfinite(request.time_limit) || request.time_limit <= 0.0)
    return fail(ErrorCode::InvalidArgument, "time limit: must be positive");
  const std::vector<std::string> known = plannerNames();
  if (std::find(known.begin(), known.end(), request.planner) == known.end())
  {
    std::string list;
    for (const std::string& name : known)
      list += (list.empty() ? "" : ", ") + name;
    return fail(ErrorCode::InvalidArgument, "planner " + request.planner + ": unknown (known: " + list + ")");
  }
  std::vector<Eigen::VectorXd> goals;
  PlanResult result;
  if (!goalStates(request, 0.5 * request.time_limit, goals, result))
    return result;

  ob::RealVectorBounds bounds(size());
  for (std::size_t i = 0; i < size(); ++i)
  {
    const Eigen::Index j = static_cast<Eigen::Index>(i);
    bounds.setLow(i, bounds_.continuous(i) ? request.start[j] - M_PI : bounds_.lower()[j]);
    bounds.setHigh(i, bounds_.continuous(i) ? request.start[j] + M_PI : bounds_.upper()[j]);
  }
  space_->setBounds(bounds);
  sampler_seed_ = request.seed * 1000003ull + 1;
  const std::size_t n = size();
  auto pdef = std::make_shared<ob::ProblemDefinition>(si_);
  ob::ScopedState<> start(si_->getStateSpace());
  fromEigen(request.start, start.get());
  pdef->addStartState(start);
  auto goal = std::make_shared<ob::GoalStates>(si_);
  for (const Eigen::VectorXd& q : goals)
  {
    ob::ScopedState<> state(si_->getStateSpace());
    fromEigen(q, state.get());
    goal->addState(state);
  }
  pdef->setGoal(goal);

  std::vector<Eigen::VectorXd> path;
  if (segmentValid(request.start, goals.front()))
  {
    path = { request.start, goals.front() };
  }
  else
  {
    // Restarts with fresh trees, a doubling budget and a halving range cut the heavy tail of sampling
    // planners' run times: a tree grown into a pocket rarely gets out, and long edges miss narrow passages.
    double budget = kFirstAttempt;
    double range = kRange;
    while (true)
    {
      pdef->clearSolutionPaths();
      const ob::PlannerPtr planner = makePlanner(request.planner, si_);
      if (planner->params().hasParam("range"))
        planner->params().setParam("range", std::to_string(range));
      planner->setProblemDefinition(pdef);
      planner->setup();
      const double remaining = request.time_limit - seconds(start_time);
      const double attempt = remaining - budget < kFirstAttempt ? remaining : budget;
      if (planner->solve(std::max(1e-3, attempt)) == ob::PlannerStatus::EXACT_SOLUTION)
        break;
      if (seconds(start_time) >= request.time_limit - 1e-3)
        return fail(ErrorCode::PlanningFailed, "planner " + request.planner + ": no path within " +
                                                   std::to_string(request.time_limit) + " s");
      budget *= 2.0;
      range = std::max(kMinRange, 0.5 * range);
    }
    const og::PathGeometric& solution = *pdef->getSolutionPath()->as<og::PathGeometric>();
    for (std::size_t i = 0; i < solution.getStateCount(); ++i)
      path.push_back(toEigen(solution.getState(i), n));
    if (request.simplify)
      simplify(path, request.shortcut_attempts, request.seed);
  }
  result.success = true;
  result.code = ErrorCode::Ok;
  result.path = path;
  result.path_length = pathLength(path);
  result.planning_time = seconds(start_time);
  return result;
}

void MotionPlanner::reduceVertices(std::vector<Eigen::VectorXd>& path)
{
  for (std::size_t i = 0; i + 2 < path.size(); ++i)
    for (std::size_t j = path.size() - 1; j > i + 1; --j)
      if (segmentValid(path[i], path[j]))
      {
        path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1), path.begin() + static_cast<std::ptrdiff_t>(j));
        break;
      }
}

void MotionPlanner::simplify(std::vector<Eigen::VectorXd>& path, int attempts, std::uint64_t seed)
{
  reduceVertices(path);
  std::mt19937_64 rng(seed);
  for (int attempt = 0, failures = 0; attempt < attempts && failures < kShortcutFailures && path.size() > 2;
       ++attempt)
  {
    std::vector<double> cumulative(1, 0.0);
    for (std::size_t i = 1; i < path.size(); ++i)
      cumulative.push_back(cumulative.back() + (path[i] - path[i - 1]).norm());
    std::uniform_real_distribution<double> along(0.0, cumulative.back());
    double a = along(rng), b = along(rng);
    if (a > b)
      std::swap(a, b);
    const std::size_t ia = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), a) -
                                                    cumulative.begin()) - 1;
    const std::size_t ib = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), b) -
                                                    cumulative.begin()) - 1;
    if (ia == ib || ib + 1 >= path.size())
    {
      ++failures;
      continue;
    }
    const auto point = [&](std::size_t i, double s) {
      const double t = (s - cumulative[i]) / std::max(cumulative[i + 1] - cumulative[i], 1e-12);
      return Eigen::VectorXd(path[i] + t * (path[i + 1] - path[i]));
    };
    const Eigen::VectorXd pa = point(ia, a), pb = point(ib, b);
    if (!segmentValid(pa, pb))
    {
      ++failures;
      continue;
    }
    failures = 0;
    std::vector<Eigen::VectorXd> shorter(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(ia + 1));
    shorter.push_back(pa);
    shorter.push_back(pb);
    shorter.insert(shorter.end(), path.begin() + static_cast<std::ptrdiff_t>(ib + 1), path.end());
    path.clear();
    for (const Eigen::VectorXd& q : shorter)
      if (path.empty() || (q - path.back()).norm() > 1e-9)
        path.push_back(q);
  }
  reduceVertices(path);
}

double pathLength(const std::vector<Eigen::VectorXd>& path)
{
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += (path[i] - path[i - 1]).norm();
  return length;
}
}  // namespace vrrw_kinematics
