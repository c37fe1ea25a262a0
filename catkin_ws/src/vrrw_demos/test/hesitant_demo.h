#pragma once
// A hesitant teacher's pick-and-place on a robot whose joints are its TCP's x, y and z (a URDF of three
// prismatic joints in the metadata, so segmentation has the TCP): pauses between and inside instructions, a
// 3 cm correction sideways above the object, a descent and a lift in two halves, a twitch when the grip takes the
// load, and while holding a vibration that the recorded velocities carry at 0.2 rad/s.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_demos/demonstration.h>

#include "scripted_demo.h"
#include "xyz_robot.h"

namespace vrrw_demos_test
{
inline ScriptedDemo hesitantPickPlace(double rate = 100.0)
{
  using namespace vrrw_demos;
  struct Move
  {
    double start, duration;
    std::vector<double> to;
  };
  const std::vector<double> home{ 0.2, 0.3, 1.2 };
  const std::vector<Move> moves{ { 1.0, 1.5, { 0.4, 0.1, 1.07 } },     // near_pick ...
                                 { 5.5, 0.5, { 0.43, 0.1, 1.07 } },    // ... corrected sideways after 3 s
                                 { 7.0, 0.8, { 0.43, 0.1, 1.01 } },    // pick: halfway down,
                                 { 9.8, 0.8, { 0.43, 0.1, 0.95 } },    // 2 s of doubt, the rest of the way
                                 { 12.5, 0.1, { 0.43, 0.1, 0.947 } },  // the grip takes the load: a 3 mm twitch
                                 { 13.5, 0.6, { 0.43, 0.1, 1.0 } },    // back_to_near_pick: halfway up,
                                 { 15.6, 0.6, { 0.43, 0.1, 1.07 } },   // then the rest after 1.5 s
                                 { 26.2, 2.0, { 0.43, -0.2, 1.07 } },  // final, 10 s later: across,
                                 { 29.2, 1.0, { 0.43, -0.2, 0.95 } } };  // and down after 1 s above the place
  const double close_start = 11.8, open_start = 31.2, end = 33.0;
  ScriptedDemo out;
  out.demo.source = "hesitant.bag";
  RobotTrack& track = addXyzRobot(out.demo, close_start, open_start);
  for (double t = 0; t <= end; t += 1.0 / rate)
  {
    RobotState state;
    state.time = t;
    std::vector<double> q = home, from = home;
    for (const Move& m : moves)
    {
      for (std::size_t j = 0; j < 3; ++j)
        if (t > m.start)
          q[j] = from[j] + (m.to[j] - from[j]) * minimumJerk((t - m.start) / m.duration);
      from = m.to;
    }
    const bool holding = t > 12.3 && t < open_start;
    state.velocities = { 0.0, 0.0, holding ? 0.2 * std::sin(2 * M_PI * 40 * t) : 0.0 };
    q[2] += holding ? 2e-5 * std::sin(2 * M_PI * 40 * t) : 0.0;  // 20 um at 40 Hz: the drives ringing
    state.positions = q;
    state.gripper = 0.8 * minimumJerk((t - close_start) / 0.5) - 0.8 * minimumJerk((t - open_start) / 0.6);
    track.states.push_back(state);
  }
  auto& box = out.demo.objects["box"];
  for (double t = 0; t <= end; t += 0.05)
  {
    TimedPose pose;
    pose.time = t;
    const RobotState held = stateAt(track, std::clamp(t, 12.7, open_start));
    pose.pose.position[0] = held.positions[0];
    pose.pose.position[1] = held.positions[1];
    pose.pose.position[2] = held.positions[2] - 0.2;
    box.push_back(pose);
  }
  out.truth = { { "near_pick", { 1.0, 6.0 } },          { "pick", { 7.0, 10.6 } },
                { "close_gripper", { 11.8, 12.3 } },    { "back_to_near_pick", { 13.5, 16.2 } },
                { "final", { 26.2, 30.2 } },            { "open_gripper", { 31.2, 31.8 } } };
  return out;
}
}  // namespace vrrw_demos_test
