#include <vrrw_demos/segmentation.h>

#include <algorithm>
#include <cmath>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/tcp_kinematics.h>

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

/// The fastest joint's speed at each state from the recorded positions: the slope of a least-squares line
/// through the states within `window` (centred), so a held load's jitter and the drives' ripple average out
/// (the recorded velocities carry them at full amplitude).
std::vector<double> positionSpeeds(const RobotTrack& track, double window)
{
  const auto& states = track.states;
  const std::size_t joints = states.empty() ? 0 : states.front().positions.size();
  std::vector<double> speed(states.size(), 0.0);
  // running sums over the window [a, b] of t, t^2 and, per joint, q and t q (t from the window's centre
  // would be exact; times from the first state keep them small enough)
  const double t0 = states.empty() ? 0.0 : states.front().time;
  double n = 0.0, st = 0.0, stt = 0.0;
  std::vector<double> sq(joints, 0.0), stq(joints, 0.0);
  auto add = [&](std::size_t k, double sign) {
    const double t = states[k].time - t0;
    n += sign;
    st += sign * t;
    stt += sign * t * t;
    for (std::size_t j = 0; j < joints; ++j)
    {
      sq[j] += sign * states[k].positions[j];
      stq[j] += sign * t * states[k].positions[j];
    }
  };
  std::size_t a = 0, b = 0;  // the window holds [a, b)
  for (std::size_t k = 0; k < states.size(); ++k)
  {
    while (b < states.size() && states[b].time - states[k].time <= 0.5 * window)
      add(b++, 1.0);
    while (states[k].time - states[a].time > 0.5 * window)
      add(a++, -1.0);
    const double spread = n * stt - st * st;
    if (n < 2.0 || !(spread > 1e-12 * n * n))
      continue;
    for (std::size_t j = 0; j < joints; ++j)
      speed[k] = std::max(speed[k], std::abs((n * stq[j] - st * sq[j]) / spread));
  }
  return speed;
}

/// The arm's own noise at rest: the 90th percentile of the speeds below a quarter of `still` (0 with fewer than
/// ten such samples).
double restNoise(std::vector<double> speed, double still)
{
  speed.erase(std::remove_if(speed.begin(), speed.end(), [still](double v) { return v >= 0.25 * still; }),
              speed.end());
  if (speed.size() < 10)
    return 0.0;
  const auto at = speed.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(speed.size() - 1));
  std::nth_element(speed.begin(), at, speed.end());
  return *at;
}

/// The most any joint moves (max - min) over [from, to].
double excursion(const RobotTrack& track, double from, double to)
{
  std::vector<double> low, high;
  for (const RobotState& state : track.states)
  {
    if (state.time < from || state.time > to)
      continue;
    if (low.empty())
      low = high = state.positions;
    for (std::size_t j = 0; j < state.positions.size(); ++j)
    {
      low[j] = std::min(low[j], state.positions[j]);
      high[j] = std::max(high[j], state.positions[j]);
    }
  }
  double largest = 0.0;
  for (std::size_t j = 0; j < low.size(); ++j)
    largest = std::max(largest, high[j] - low[j]);
  return largest;
}

/// The TCP's position at every recorded state, by the demonstration's own URDF; empty without one.
std::vector<Eigen::Vector3d> tcpPath(const Demonstration& demo, const RobotTrack& track)
{
  std::vector<Eigen::Vector3d> path;
  try
  {
    const TcpKinematics tcp(demo, track);
    for (const RobotState& state : track.states)
      path.push_back(tcp.at(state).translation());
  }
  catch (const DemoError&)
  {
    path.clear();
  }
  return path;
}

/// True when every TCP position of the states in [from, to] lies within `tolerance` of the straight line
/// between the TCP at `from` and at `to`.
bool straight(const RobotTrack& track, const std::vector<Eigen::Vector3d>& tcp, double from, double to,
              double tolerance)
{
  std::size_t first = 0, last = 0;
  for (std::size_t k = 0; k < track.states.size(); ++k)
  {
    if (track.states[k].time <= from)
      first = k;
    if (track.states[k].time <= to)
      last = k;
  }
  const Eigen::Vector3d a = tcp[first], b = tcp[last];
  const Eigen::Vector3d along = b - a;
  const double length2 = along.squaredNorm();
  for (std::size_t k = first; k <= last; ++k)
  {
    const double u = length2 > 0.0 ? std::clamp((tcp[k] - a).dot(along) / length2, 0.0, 1.0) : 0.0;
    if ((tcp[k] - (a + u * along)).norm() > tolerance)
      return false;
  }
  return true;
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
  if (t <= states.front().time || t >= states.back().time)
  {
    RobotState out = t <= states.front().time ? states.front() : states.back();
    out.time = t;  // the recorded state held: a slice from before the first state still starts at its start
    return out;
  }
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
  std::vector<double> times;
  for (const RobotState& state : track.states)
    times.push_back(state.time);
  const std::vector<double> speed = positionSpeeds(track, options.speed_window);
  const double rest = std::max(options.rest_speed, 2.0 * restNoise(speed, options.still_speed));
  std::vector<Interval> out;
  for (const Interval& motion : motions(times, [&](std::size_t k) { return speed[k]; }, options.still_speed, rest,
                                        options.min_still))
    if (excursion(track, motion.first, motion.second) >= options.min_motion)
      out.push_back(motion);
  return out;
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

  // The arm motions between `from` and `to`, split in two at the grasp's side: before it the motions on the
  // straight way into the grasp are `pick` (the ones before them `near_pick`), after it the motions on the
  // straight way out of it are `back_to_near_pick` (the ones after them `final`). Without the TCP the motion
  // next to the grasp alone. Stops at waypoints of the far instruction stay in it.
  const std::vector<Eigen::Vector3d> tcp = tcpPath(demo, track);
  auto armSegments = [&](double from, double to, const char* first, const char* second, bool before_grasp) {
    std::vector<Interval> inside;
    for (const Interval& motion : arm)
      if (motion.second > from && motion.first < to)
        inside.push_back({ std::max(motion.first, from), std::min(motion.second, to) });
    if (inside.empty())
      return;
    std::size_t split = before_grasp ? inside.size() - 1 : 1;  // the first motion of `second`
    if (!tcp.empty() && before_grasp)
      while (split > 0 && straight(track, tcp, inside[split - 1].first, to, options.line_tolerance))
        --split;
    if (!tcp.empty() && !before_grasp)
      while (split < inside.size() && straight(track, tcp, from, inside[split].second, options.line_tolerance))
        ++split;
    if (split == 0 || split == inside.size())  // one instruction: pick, or final (a single motion is final)
    {
      if (before_grasp)
        out.warnings.push_back(std::string("no motion before '") + second + "' off its way: no '" + first +
                               "' instruction");
      out.segments.push_back({ second, inside.front().first, inside.back().second, false, 0.0, "" });
      return;
    }
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
