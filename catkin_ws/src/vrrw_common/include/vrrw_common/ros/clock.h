#pragma once
// Waiting for this process' ROS clock to reach an instant of a lockstep simulation.
#include <ros/ros.h>

#include <chrono>
#include <thread>

namespace vrrw_common
{
/// \brief Waits (at most `wall_seconds`) until ros::Time::now() reached `instant`. In lockstep a step's answer
/// or the state where the simulation waits may arrive before its /clock (roscpp serves /clock on a thread of its
/// own), and what a process stamps with the ROS clock (an actionlib goal, an event) must carry that instant on
/// every run.
inline void awaitClock(const ros::Time& instant, double wall_seconds = 0.5)
{
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(wall_seconds);
  while (ros::Time::now() < instant && std::chrono::steady_clock::now() < end && ros::ok())
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}
}  // namespace vrrw_common
