#include <vrrw_demos/replay_path.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vrrw_demos/demo_error.h>

namespace vrrw_demos
{
namespace
{
constexpr int kSmoothingPasses = 200;
/// s (of the unstretched replay) on each side of a stretched interval over which its stretch fades: the
/// velocity eases into and out of a slowed stretch instead of stepping (a step is an acceleration; at
/// 2 rad/s a third slower over 0.25 s asks 2.7 rad/s^2 of easing, inside a UR's 3.14).
constexpr double kEaseSeconds = 0.25;
/// Rounds of local stretching; a path still outside its limits after them is stretched uniformly.
constexpr int kMaxRounds = 100;
/// Stretch a little more than needed: the retimed path lies strictly inside the limits.
constexpr double kMargin = 1.0 + 1e-3;

/// Binomial smoothing passes, each result clamped to [recorded - tolerance, recorded + tolerance].
std::vector<double> smooth(const std::vector<double>& recorded, double tolerance)
{
  std::vector<double> q = recorded, next = recorded;
  for (int pass = 0; pass < kSmoothingPasses; ++pass)
  {
    for (std::size_t k = 1; k + 1 < q.size(); ++k)
      next[k] = std::clamp(0.25 * (q[k - 1] + 2 * q[k] + q[k + 1]), recorded[k] - tolerance, recorded[k] + tolerance);
    q.swap(next);
  }
  return q;
}

void centralVelocities(vrrw_trajectory::JointTrajectory& trajectory)
{
  auto& points = trajectory.points;
  const std::size_t n = trajectory.joint_names.size();
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k].velocities.assign(n, 0.0);
    if (k == 0 || k + 1 == points.size())
      continue;  // the controller starts and ends at rest
    const double dt = points[k + 1].time - points[k - 1].time;
    for (std::size_t j = 0; j < n; ++j)
      points[k].velocities[j] = (points[k + 1].positions[j] - points[k - 1].positions[j]) / dt;
  }
}

/// How much slower interval k (from point k-1 to point k) must run for the velocities at both its ends
/// and the acceleration across it to be within the limits (velocities scale with 1/f, accelerations
/// with 1/f^2), and the limit that asks the most.
struct Need
{
  double factor = 1.0;
  std::string limit;
};

std::vector<Need> needs(const vrrw_trajectory::JointTrajectory& trajectory, const ReplayOptions& options)
{
  const auto& points = trajectory.points;
  std::vector<Need> out(points.size());
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    const double dt = points[k].time - points[k - 1].time;
    for (std::size_t j = 0; j < trajectory.joint_names.size(); ++j)
    {
      const double v0 = points[k - 1].velocities[j], v1 = points[k].velocities[j];
      if (!options.max_velocity.empty())
      {
        const double f = std::max(std::abs(v0), std::abs(v1)) / options.max_velocity[j];
        if (f > out[k].factor)
          out[k] = { f, trajectory.joint_names[j] + " velocity" };
      }
      if (!options.max_acceleration.empty())
      {
        const double f = std::sqrt(std::abs(v1 - v0) / dt / options.max_acceleration[j]);
        if (f > out[k].factor)
          out[k] = { f, trajectory.joint_names[j] + " acceleration" };
      }
    }
  }
  return out;
}

/// Point times from the base intervals stretched by their factors; velocities follow.
void applyStretch(vrrw_trajectory::JointTrajectory& trajectory, const std::vector<double>& base,
                  const std::vector<double>& factor)
{
  for (std::size_t k = 1; k < trajectory.points.size(); ++k)
    trajectory.points[k].time = trajectory.points[k - 1].time + base[k] * factor[k];
  centralVelocities(trajectory);
}

/// Stretches the intervals that break a limit (and eases into them) until none does; where rounds run
/// out, the rest is uniform. Returns the factor of every interval and fills the stretches.
void retime(ReplayPath& out, const ReplayOptions& options)
{
  auto& points = out.trajectory.points;
  const std::size_t count = points.size();
  std::vector<double> base(count, 0.0), factor(count, 1.0);
  std::vector<std::string> cause(count);
  std::vector<double> middle(count, 0.0);  // the unstretched time of each interval's middle
  for (std::size_t k = 1; k < count; ++k)
  {
    base[k] = points[k].time - points[k - 1].time;
    middle[k] = 0.5 * (points[k].time + points[k - 1].time);
  }
  for (int round = 0; round <= kMaxRounds; ++round)
  {
    applyStretch(out.trajectory, base, factor);
    const std::vector<Need> need = needs(out.trajectory, options);
    const auto worst = std::max_element(need.begin(), need.end(),
                                        [](const Need& a, const Need& b) { return a.factor < b.factor; });
    if (worst->factor <= 1.0)
      break;
    if (round == kMaxRounds)
    {
      for (std::size_t k = 1; k < count; ++k)
        factor[k] *= worst->factor * kMargin;
      applyStretch(out.trajectory, base, factor);
      break;
    }
    const std::vector<double> before = factor;
    for (std::size_t k = 1; k < count; ++k)
    {
      if (need[k].factor <= 1.0)
        continue;
      if (cause[k].empty())
        cause[k] = need[k].limit;
      // a tent around interval k: its own target, fading to none kEaseSeconds away on either side
      const double target = before[k] * need[k].factor * kMargin;
      const auto raise = [&](std::size_t i) {
        const double distance = std::abs(middle[i] - middle[k]);
        if (distance >= kEaseSeconds)
          return false;
        factor[i] = std::max(factor[i], 1.0 + (target - 1.0) * (1.0 - distance / kEaseSeconds));
        return true;
      };
      for (std::size_t i = k; i >= 1 && raise(i); --i)
      {
      }
      for (std::size_t i = k + 1; i < count && raise(i); ++i)
      {
      }
    }
  }

  for (std::size_t k = 1; k < count; ++k)
  {
    if (factor[k] <= 1.0)
      continue;
    if (out.stretches.empty() || out.recorded_times[k - 1] > out.stretches.back().end)
      out.stretches.push_back({ out.recorded_times[k - 1], out.recorded_times[k], 1.0, 0.0, "" });
    Stretch& stretch = out.stretches.back();
    stretch.end = out.recorded_times[k];
    stretch.factor = std::max(stretch.factor, factor[k]);
    stretch.added += base[k] * (factor[k] - 1.0);
    if (stretch.limit.empty())
      stretch.limit = cause[k];
  }
  for (Stretch& stretch : out.stretches)
    if (stretch.limit.empty())
      stretch.limit = "easing";
}

std::string number(double value, const char* format)
{
  char text[32];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}
}  // namespace

double ReplayPath::recordedTime(double t) const
{
  const auto& points = trajectory.points;
  if (points.empty())
    return 0.0;
  if (t <= points.front().time)
    return recorded_times.front();
  if (t >= points.back().time)
    return recorded_times.back();
  const auto after = std::upper_bound(points.begin(), points.end(), t,
                                      [](double time, const auto& point) { return time < point.time; });
  const std::size_t k = static_cast<std::size_t>(after - points.begin());
  const double s = (t - points[k - 1].time) / (points[k].time - points[k - 1].time);
  return recorded_times[k - 1] + s * (recorded_times[k] - recorded_times[k - 1]);
}

double ReplayPath::replayTime(double recorded) const
{
  const auto& points = trajectory.points;
  if (points.empty())
    return 0.0;
  if (recorded <= recorded_times.front())
    return points.front().time + (recorded - recorded_times.front()) / speed;
  if (recorded >= recorded_times.back())
    return points.back().time + (recorded - recorded_times.back()) / speed;
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(recorded_times.begin(), recorded_times.end(), recorded) -
                               recorded_times.begin());
  const double s = (recorded - recorded_times[k - 1]) / (recorded_times[k] - recorded_times[k - 1]);
  return points[k - 1].time + s * (points[k].time - points[k - 1].time);
}

std::string ReplayPath::retimingSummary() const
{
  if (stretches.empty())
    return "the recorded timing (every joint within its velocity and acceleration limits)";
  double added = 0.0;
  for (const Stretch& s : stretches)
    added += s.added;
  std::string text = "the recorded timing but for " + std::to_string(stretches.size()) + " stretch" +
                     (stretches.size() == 1 ? "" : "es") + " slowed into the limits (+" + number(added, "%.2f") +
                     " s, x" + number(time_scale, "%.3f") + " overall):";
  constexpr std::size_t kShown = 5;
  for (std::size_t i = 0; i < stretches.size() && i < kShown; ++i)
    text += (i ? "; " : " ") + number(stretches[i].start, "%.2f") + "-" + number(stretches[i].end, "%.2f") + " s x" +
            number(stretches[i].factor, "%.3f") + " (" + stretches[i].limit + ")";
  if (stretches.size() > kShown)
    text += "; and " + std::to_string(stretches.size() - kShown) + " more";
  return text;
}

ReplayPath replayPath(const RobotTrack& track, const ReplayOptions& options)
{
  const std::size_t n = track.joint_names.size();
  if (track.states.size() < 2)
    throw DemoError("robot '" + track.robot + "': a replay needs at least two recorded states");
  if ((!options.max_velocity.empty() && options.max_velocity.size() != n) ||
      (!options.max_acceleration.empty() && options.max_acceleration.size() != n))
    throw DemoError("robot '" + track.robot + "': limits for " + std::to_string(options.max_velocity.size()) +
                    " joints, the recording has " + std::to_string(n));
  if (!(options.speed >= ReplayBounds::kMinSpeed && options.speed <= ReplayBounds::kMaxSpeed))
    throw DemoError("speed: " + number(options.speed, "%g") + " is outside [" + number(ReplayBounds::kMinSpeed, "%g") +
                    ", " + number(ReplayBounds::kMaxSpeed, "%g") + "]");
  if (!(options.tolerance >= 0.0 && options.tolerance <= ReplayBounds::kMaxTolerance))
    throw DemoError("tolerance: " + number(options.tolerance, "%g") + " rad is outside [0, " +
                    number(ReplayBounds::kMaxTolerance, "%g") + "]");
  for (const auto* limits : { &options.max_velocity, &options.max_acceleration })
    for (std::size_t j = 0; j < limits->size(); ++j)
      if (!((*limits)[j] > 0.0))
        throw DemoError("robot '" + track.robot + "': joint " + track.joint_names[j] + ": limit " +
                        number((*limits)[j], "%g") + " is not positive");

  const double recorded = track.states.back().time - track.states.front().time;
  if (recorded / options.speed > ReplayBounds::kMaxDuration)
    throw DemoError("robot '" + track.robot + "': " + number(recorded, "%.0f") + " s recorded at speed " +
                    number(options.speed, "%g") + " would last more than the bound of " +
                    number(ReplayBounds::kMaxDuration, "%.0f") + " s");

  ReplayPath out;
  out.speed = options.speed;
  std::vector<std::vector<double>> smoothed(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    std::vector<double> recorded;
    for (const RobotState& state : track.states)
      recorded.push_back(state.positions[j]);
    smoothed[j] = smooth(recorded, options.tolerance);
    for (std::size_t k = 0; k < recorded.size(); ++k)
      out.max_deviation = std::max(out.max_deviation, std::abs(smoothed[j][k] - recorded[k]));
  }

  auto& trajectory = out.trajectory;
  trajectory.joint_names = track.joint_names;
  const double t0 = track.states.front().time;
  const std::size_t last = track.states.size() - 1;
  for (std::size_t k = 0; k <= last; ++k)
  {
    const double t = track.states[k].time;
    const bool keep = trajectory.points.empty() || k == last ||
                      (t - t0 - trajectory.points.back().time * options.speed >= options.min_point_spacing - 1e-9 &&
                       track.states[last].time - t >= options.min_point_spacing / 2);
    if (!keep)
      continue;
    vrrw_trajectory::TrajectoryPoint point;
    point.time = (t - t0) / options.speed;
    for (std::size_t j = 0; j < n; ++j)
      point.positions.push_back(smoothed[j][k]);
    trajectory.points.push_back(std::move(point));
    out.recorded_times.push_back(t - t0);
  }
  const double unstretched = trajectory.duration();
  retime(out, options);
  out.time_scale = unstretched > 0.0 ? trajectory.duration() / unstretched : 1.0;
  if (trajectory.duration() > ReplayBounds::kMaxDuration)
    throw DemoError("robot '" + track.robot + "': the replay would last " + number(trajectory.duration(), "%.0f") +
                    " s, more than the bound of " + number(ReplayBounds::kMaxDuration, "%.0f") + " s");
  return out;
}
}  // namespace vrrw_demos
