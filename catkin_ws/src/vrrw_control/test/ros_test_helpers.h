#pragma once
// Helpers shared by the node tests: a joint_states recorder and goal builders.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <iostream>
#include <mutex>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

namespace vrrw_control_test
{
/// Records every joint_states message of one robot.
class JointStateLog
{
public:
  JointStateLog(ros::NodeHandle& nh, const std::string& topic)
    : sub_(nh.subscribe(topic, 5000, &JointStateLog::onMsg, this, ros::TransportHints().tcpNoDelay()))
  {
  }
  std::vector<sensor_msgs::JointState> since(const ros::Time& t) const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<sensor_msgs::JointState> out;
    for (const auto& m : log_)
      if (m.header.stamp >= t)
        out.push_back(m);
    return out;
  }
  bool waitLatest(sensor_msgs::JointState& out, double timeout = 5.0) const
  {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::WallTime::now() < end)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!log_.empty())
        {
          out = log_.back();
          return true;
        }
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  /// Waits (wall clock, bounded) for the message stamped `stamp` (the state where the simulation waits).
  bool waitFor(const ros::Time& stamp, sensor_msgs::JointState& out, double timeout = 5.0) const
  {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::WallTime::now() < end)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto m = log_.rbegin(); m != log_.rend(); ++m)
          if (m->header.stamp == stamp)
            return out = *m, true;
      }
      ros::WallDuration(0.002).sleep();
    }
    return false;
  }

  /// The latest stamp received (zero before the first message).
  ros::Time newest() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return newest_;
  }

  /// Waits (wall clock, at most `seconds`) until a message stamped after `stamp` has arrived.
  bool waitNewer(const ros::Time& stamp, double seconds) const
  {
    std::unique_lock<std::mutex> lock(mutex_);
    return arrived_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return newest_ > stamp; });
  }

private:
  void onMsg(const sensor_msgs::JointState& m)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    log_.push_back(m);
    newest_ = std::max(newest_, m.header.stamp);
    arrived_.notify_all();
  }
  mutable std::mutex mutex_;  ///< protects log_ and newest_ (written by the spinner, read by the test)
  mutable std::condition_variable arrived_;  ///< notified with every message
  std::vector<sensor_msgs::JointState> log_;
  ros::Time newest_;
  ros::Subscriber sub_;
};

inline std::vector<std::string> armJoints(const std::string& p)
{
  return { p + "shoulder_pan_joint", p + "shoulder_lift_joint", p + "elbow_joint",
           p + "wrist_1_joint",      p + "wrist_2_joint",       p + "wrist_3_joint" };
}

inline trajectory_msgs::JointTrajectoryPoint point(double t, std::vector<double> q, std::vector<double> v = {},
                                                   std::vector<double> a = {})
{
  trajectory_msgs::JointTrajectoryPoint p;
  p.positions = q;
  p.velocities = v;
  p.accelerations = a;
  p.time_from_start = ros::Duration(t);
  return p;
}

/// A rest-to-rest cubic move of every joint from `from` by `delta` over `duration`.
inline control_msgs::FollowJointTrajectoryGoal move(const std::string& prefix, const std::vector<double>& from,
                                                    const std::vector<double>& delta, double duration)
{
  control_msgs::FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = armJoints(prefix);
  std::vector<double> to(from);
  for (size_t j = 0; j < to.size(); ++j)
    to[j] += delta[j];
  const std::vector<double> zero(from.size(), 0.0);
  g.trajectory.points = { point(0.0, from, zero), point(duration, to, zero) };
  return g;
}

/// Largest |q[k+1] - q[k]| / dt and |second difference| / dt^2 over a recorded joint_states run.
inline void finiteDifferences(const std::vector<sensor_msgs::JointState>& run, double& max_velocity,
                              double& max_acceleration)
{
  max_velocity = max_acceleration = 0.0;
  for (size_t k = 1; k < run.size(); ++k)
  {
    const double dt = (run[k].header.stamp - run[k - 1].header.stamp).toSec();
    for (size_t j = 0; j < run[k].position.size(); ++j)
    {
      const double v = (run[k].position[j] - run[k - 1].position[j]) / dt;
      max_velocity = std::max(max_velocity, std::abs(v));
      if (k >= 2)
      {
        const double dt0 = (run[k - 1].header.stamp - run[k - 2].header.stamp).toSec();
        const double v0 = (run[k - 1].position[j] - run[k - 2].position[j]) / dt0;
        max_acceleration = std::max(max_acceleration, std::abs(v - v0) / (0.5 * (dt + dt0)));
      }
    }
  }
}

/// Prints the largest finite-difference velocity and acceleration of a run and expects them within the
/// limits (5 % on the acceleration for the differencing of jittered stamps).
inline void expectWithinLimits(const std::vector<sensor_msgs::JointState>& run, const std::string& what,
                               double velocity_limit, double acceleration_limit)
{
  double vmax, amax;
  finiteDifferences(run, vmax, amax);
  std::cout << what << ": " << run.size() << " samples, max |qd| " << vmax << " rad/s, max |qdd| " << amax
            << " rad/s^2" << std::endl;
  EXPECT_LE(vmax, velocity_limit * 1.01) << what;
  EXPECT_LE(amax, acceleration_limit * 1.05) << what;
}
}  // namespace vrrw_control_test

