#include <vrrw_demos/segmentation.h>

#include <algorithm>
#include <cmath>

#include <vrrw_demos/demo_error.h>

namespace vrrw_demos
{
namespace
{
using Interval = std::pair<double, double>;

/// rad (m): a gripper goal whose motion ends farther than this from it stalled on something.
constexpr double kStallGap = 0.02;

/// Intervals where speed(k) > fast, pauses shorter than min_still merged, ends walked out to rest speed.
template <class Speed>
std::vector<Interval> motions(const std::vector<double>& times, Speed speed, double fast, double rest,
                              double min_still)
{
  const std::size_t count = times.size();
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (speed(k) <= fast)
      continue;
    std::size_t end = k;
    while (end + 1 < count && speed(end + 1) > fast)
      ++end;
    if (!runs.empty() && times[k] - times[runs.back().second] < min_still)
      runs.back().second = end;
    else
      runs.push_back({ k, end });
    k = end;
  }
  std::vector<Interval> out;
  for (std::size_t r = 0; r < runs.size(); ++r)
  {
    std::size_t first = runs[r].first, last = runs[r].second;
    const std::size_t floor = r == 0 ? 0 : (runs[r - 1].second + first) / 2;
    const std::size_t ceiling = r + 1 == runs.size() ? count - 1 : (last + runs[r + 1].first) / 2;
    while (first > floor && speed(first - 1) > rest)
      --first;
    while (last < ceiling && speed(last + 1) > rest)
      ++last;
    // The motion begins after the last resting sample and ends at the first one.
    out.push_back({ times[first > 0 ? first - 1 : 0], times[std::min(last + 1, count - 1)] });
  }
  return out;
}

double distance(const Pose& a, const Pose& b)
{
  return std::sqrt(std::pow(a.position[0] - b.position[0], 2) + std::pow(a.position[1] - b.position[1], 2) +
                   std::pow(a.position[2] - b.position[2], 2));
}

std::string heldObject(const Demonstration& demo, double from, double to, double moved)
{
  std::string held;
  double most = moved;
  for (const auto& entry : demo.objects)
  {
    const std::string& name = entry.first;
    const Pose* a = objectPoseAt(demo, name, from);
    const Pose* b = objectPoseAt(demo, name, to);
    if (a && b && distance(*a, *b) > most)
    {
      most = distance(*a, *b);
      held = name;
    }
  }
  return held;
}

struct GripperAction
{
  double start, end, target;
  double direction;  ///< +1 or -1: the sign of the motion (of the goal, when there is one)
  bool stalled;      ///< stopped short of its goal: closed on an object
};

/// The closing direction: that of an action that stalled on an object, else that of the first action
/// after the arm began to move (a pick-and-place closes first); 0 when there is no action.
double closingDirection(const std::vector<GripperAction>& actions, double arm_start)
{
  for (const GripperAction& action : actions)
    if (action.stalled)
      return action.direction;
  for (const GripperAction& action : actions)
    if (action.start >= arm_start)
      return action.direction;
  return actions.empty() ? 0.0 : actions.front().direction;
}

std::vector<GripperAction> gripperActions(const RobotTrack& track, const SegmentationOptions& options)
{
  std::vector<double> times, speed;
  for (std::size_t k = 0; k < track.states.size(); ++k)
  {
    times.push_back(track.states[k].time);
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, track.states.size() - 1);
    const double dt = track.states[b].time - track.states[a].time;
    speed.push_back(dt > 0 ? std::abs(track.states[b].gripper - track.states[a].gripper) / dt : 0.0);
  }
  const auto moves = motions(times, [&](std::size_t k) { return speed[k]; }, options.gripper_speed,
                             options.gripper_speed / 4, options.min_still);
  std::vector<GripperAction> actions;
  for (const GripperGoal& goal : track.gripper_goals)
  {
    // The goal's motion: the first gripper motion ending after the goal; none: it was there already.
    double end = goal.time;
    for (const Interval& move : moves)
      if (move.second > goal.time && move.first < goal.time + 1.0)
      {
        end = move.second;
        break;
      }
    const double from = stateAt(track, goal.time).gripper, reached = stateAt(track, end).gripper;
    if (std::abs(goal.position - from) < kStallGap && end == goal.time)
      continue;  // asked to be where it was: nothing happened
    actions.push_back({ goal.time, end, goal.position, goal.position >= from ? 1.0 : -1.0,
                        std::abs(reached - goal.position) > kStallGap });
  }
  if (track.gripper_goals.empty())
    for (const Interval& move : moves)
    {
      const double from = stateAt(track, move.first).gripper, reached = stateAt(track, move.second).gripper;
      actions.push_back({ move.first, move.second, reached, reached >= from ? 1.0 : -1.0, false });
    }
  return actions;
}
}  // namespace

Segment findSegment(const Demonstration& demo, const RobotTrack& track, const std::string& name)
{
  const Segmentation segmentation = segmentPickPlace(track, demo);
  std::string found;
  for (const Segment& segment : segmentation.segments)
  {
    if (segment.name == name)
      return segment;
    found += (found.empty() ? "" : ", ") + segment.name;
  }
  throw DemoError(demo.source + ": robot '" + track.robot + "' has no segment '" + name + "' (found: " +
                  (found.empty() ? "none" : found) + ")");
}

RobotState stateAt(const RobotTrack& track, double t)
{
  const auto& states = track.states;
  if (t <= states.front().time)
    return states.front();
  if (t >= states.back().time)
    return states.back();
  const auto after = std::upper_bound(states.begin(), states.end(), t,
                                      [](double time, const RobotState& s) { return time < s.time; });
  const RobotState& b = *after;
  const RobotState& a = *(after - 1);
  const double w = (t - a.time) / (b.time - a.time);
  RobotState out = a;
  out.time = t;
  for (std::size_t j = 0; j < a.positions.size(); ++j)
  {
    out.positions[j] = a.positions[j] + w * (b.positions[j] - a.positions[j]);
    out.velocities[j] = a.velocities[j] + w * (b.velocities[j] - a.velocities[j]);
  }
  out.gripper = a.gripper + w * (b.gripper - a.gripper);
  return out;
}

RobotTrack slice(const RobotTrack& track, double start, double end)
{
  RobotTrack out = track;
  out.states.clear();
  out.gripper_goals.clear();
  out.states.push_back(stateAt(track, start));
  for (const RobotState& state : track.states)
    if (state.time > start && state.time < end)
      out.states.push_back(state);
  if (end > start)
    out.states.push_back(stateAt(track, end));
  for (const GripperGoal& goal : track.gripper_goals)
    if (goal.time >= start && goal.time <= end)
      out.gripper_goals.push_back(goal);
  return out;
}

std::vector<std::pair<double, double>> armMotions(const RobotTrack& track, const SegmentationOptions& options)
{
  std::vector<double> times, speed;
  for (const RobotState& state : track.states)
  {
    times.push_back(state.time);
    double fastest = 0.0;
    for (double v : state.velocities)
      fastest = std::max(fastest, std::abs(v));
    speed.push_back(fastest);
  }
  return motions(times, [&](std::size_t k) { return speed[k]; }, options.still_speed, options.rest_speed,
                 options.min_still);
}

Segmentation segmentPickPlace(const RobotTrack& track, const Demonstration& demo, const SegmentationOptions& options)
{
  Segmentation out;
  if (track.states.size() < 2)
  {
    out.warnings.push_back("robot '" + track.robot + "': fewer than two recorded states");
    return out;
  }
  const auto arm = armMotions(track, options);
  const auto actions = gripperActions(track, options);
  if (arm.empty())
  {
    out.warnings.push_back("robot '" + track.robot + "': the arm never moved (speed above " +
                           std::to_string(options.still_speed) + " rad/s)");
    return out;
  }
  const GripperAction* close = nullptr;
  const GripperAction* open = nullptr;
  const double closing = closingDirection(actions, arm.front().first);
  for (const GripperAction& action : actions)
    if (!close && action.direction == closing)
      close = &action;
    else if (close && !open && action.direction != closing)
      open = &action;
  const double close_time = close ? close->start : track.states.back().time;
  const double open_time = open ? open->start : track.states.back().time;

  // The arm motions between `from` and `to`, split in two at the rest next to the grasp: before it the
  // motion into the grasp is `pick` (the ones before it `near_pick`), after it the motion out of the grasp is
  // `back_to_near_pick` (the ones after it `final`). Stops at waypoints of the far instruction stay in it.
  auto armSegments = [&](double from, double to, const char* first, const char* second, bool before_grasp) {
    std::vector<Interval> inside;
    for (const Interval& motion : arm)
      if (motion.second > from && motion.first < to)
        inside.push_back({ std::max(motion.first, from), std::min(motion.second, to) });
    if (inside.empty())
      return;
    if (inside.size() == 1)
    {
      if (before_grasp)
        out.warnings.push_back(std::string("no pause before '") + second + "': no '" + first + "' instruction");
      out.segments.push_back({ second, inside.front().first, inside.front().second, false, 0.0, "" });
      return;
    }
    const std::size_t split = before_grasp ? inside.size() - 1 : 1;  // the first motion of `second`
    out.segments.push_back({ first, inside.front().first, inside[split - 1].second, false, 0.0, "" });
    out.segments.push_back({ second, inside[split].first, inside.back().second, false, 0.0, "" });
  };
  armSegments(arm.front().first, close_time, "near_pick", "pick", true);
  if (!close)
  {
    out.warnings.push_back("robot '" + track.robot + "': the gripper never moved: no close_gripper");
    return out;
  }
  const std::string object = heldObject(demo, close->end, open_time, options.object_moved);
  out.segments.push_back({ "close_gripper", close->start, close->end, true, close->target, object });
  const std::size_t before_place = out.segments.size();
  armSegments(close->end, open_time, "back_to_near_pick", "final", false);
  for (std::size_t s = before_place; s < out.segments.size(); ++s)
    out.segments[s].object = object;
  if (!open)
  {
    out.warnings.push_back("robot '" + track.robot + "': no gripper action after close: no open_gripper");
    return out;
  }
  out.segments.push_back({ "open_gripper", open->start, open->end, true, open->target, object });
  return out;
}
}  // namespace vrrw_demos
