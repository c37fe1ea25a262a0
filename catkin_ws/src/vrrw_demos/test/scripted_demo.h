#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <random>
#include <vector>

#include <vrrw_demos/demonstration.h>

namespace vrrw_demos_test
{
/// A scripted pick-and-place with known instruction boundaries: minimum-jerk arm motions with rests
/// between them, a cubic gripper close and open, a drill that moves with the gripper in between.
struct ScriptedDemo
{
  vrrw_demos::Demonstration demo;
  std::vector<std::pair<const char*, std::pair<double, double>>> truth;  ///< segment name -> [start, end]
};

inline double minimumJerk(double s)
{
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (10 - 15 * s + 6 * s * s);
}

inline double minimumJerkRate(double s)
{
  return s <= 0 || s >= 1 ? 0.0 : 30 * s * s * (1 - s) * (1 - s);
}

/// `waypoint_stops`: the approach rests halfway and the carry rests above the place (a ghost-drive through a
/// waypoint), with the same instruction boundaries.
inline ScriptedDemo scriptedPickPlace(double rate = 250.0, double jitter = 2e-4, unsigned seed = 1,
                                      bool waypoint_stops = false)
{
  using namespace vrrw_demos;
  struct Motion
  {
    double start, duration;
    std::vector<double> to;
  };
  const std::vector<double> home{ 0, -1.57, 1.2, -1.2, -1.57, 0 };
  std::vector<Motion> arm{ { 0.5, 1.5, { 0.6, -1.2, 1.4, -1.7, -1.57, 0.3 } },    // near_pick
                           { 2.6, 1.0, { 0.6, -1.0, 1.6, -2.1, -1.57, 0.3 } },    // pick
                           { 4.9, 1.0, { 0.6, -1.2, 1.4, -1.7, -1.57, 0.3 } },    // back_to_near_pick
                           { 6.4, 2.0, { -0.5, -1.1, 1.5, -1.9, -1.57, -0.4 } } };  // final
  if (waypoint_stops)
    arm = { { 0.5, 0.6, { 0.3, -1.4, 1.3, -1.45, -1.57, 0.15 } },  // near_pick, halfway
            { 1.4, 0.6, { 0.6, -1.2, 1.4, -1.7, -1.57, 0.3 } },
            { 2.6, 1.0, { 0.6, -1.0, 1.6, -2.1, -1.57, 0.3 } },
            { 4.9, 1.0, { 0.6, -1.2, 1.4, -1.7, -1.57, 0.3 } },
            { 6.4, 1.2, { -0.5, -1.2, 1.4, -1.7, -1.57, -0.4 } },  // final, above the place
            { 7.9, 0.5, { -0.5, -1.1, 1.5, -1.9, -1.57, -0.4 } } };
  const double close_start = 3.9, close_duration = 0.7, open_start = 8.8, open_duration = 0.7;
  ScriptedDemo out;
  RobotTrack& track = out.demo.robots.emplace_back();
  track.robot = "ur5e";
  for (const char* joint : { "shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3" })
    track.joint_names.push_back(std::string("ur5e_") + joint + "_joint");
  track.gripper_joint = "ur5e_finger_joint";
  track.gripper_goals = { { close_start, 0.8 }, { open_start, 0.0 } };
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-jitter, jitter);
  for (double t = 0; t <= 10.0; t += 1.0 / rate)
  {
    RobotState state;
    state.time = t;
    std::vector<double> q = home, qd(6, 0.0);
    std::vector<double> from = home;
    for (const Motion& m : arm)
    {
      const double s = (t - m.start) / m.duration;
      for (std::size_t j = 0; j < 6; ++j)
      {
        if (s > 0)
          q[j] = from[j] + (m.to[j] - from[j]) * minimumJerk(s);
        if (s > 0 && s < 1)
          qd[j] = (m.to[j] - from[j]) * minimumJerkRate(s) / m.duration;
      }
      from = m.to;
    }
    for (std::size_t j = 0; j < 6; ++j)
      q[j] += noise(rng);
    state.positions = q;
    state.velocities = qd;
    const double close = minimumJerk((t - close_start) / close_duration);
    const double open = minimumJerk((t - open_start) / open_duration);
    state.gripper = 0.8 * close - 0.8 * open;
    track.states.push_back(state);
  }
  auto& drill = out.demo.objects["drill"];
  for (double t = 0; t <= 10.0; t += 0.02)
  {
    TimedPose pose;
    pose.time = t;
    const double carried = std::clamp((t - 4.9) / 3.5, 0.0, 1.0);
    pose.pose.position[0] = 0.15 + 0.1 * carried;
    pose.pose.position[1] = 0.25 - 0.5 * carried;
    pose.pose.position[2] = 0.75;
    drill.push_back(pose);
  }
  auto& bin = out.demo.objects["bin"];
  bin.push_back({});
  out.truth = { { "near_pick", { 0.5, 2.0 } },        { "pick", { 2.6, 3.6 } },
                { "close_gripper", { 3.9, 4.6 } },    { "back_to_near_pick", { 4.9, 5.9 } },
                { "final", { 6.4, 8.4 } },            { "open_gripper", { 8.8, 9.5 } } };
  return out;
}
}  // namespace vrrw_demos_test
