#pragma once
// What the node tests share: the scene's arm for FK, the latest ghost and robot states, the event log.
#include <functional>
#include <gtest/gtest.h>
#include <mutex>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_msgs/Event.h>
#include <vrrw_scene/scene_loader.h>

namespace vrrw_interaction_test
{
/// The latest message of a topic, and a count.
template <class Msg>
class Latest
{
public:
  Latest(ros::NodeHandle& nh, const std::string& topic)
    : sub_(nh.subscribe<Msg>(topic, 100, [this](const typename Msg::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      all_.push_back(*m);
    }))
  {
  }
  bool wait(double timeout = 5.0, std::size_t count = 1) const
  {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout); ros::WallTime::now() < end;
         ros::WallDuration(0.01).sleep())
      if (size() >= count)
        return true;
    return false;
  }
  Msg last() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return all_.empty() ? Msg() : all_.back();
  }
  std::vector<Msg> all() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return all_;
  }
  std::size_t size() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return all_.size();
  }

private:
  mutable std::mutex mutex_;
  std::vector<Msg> all_;
  ros::Subscriber sub_;
};

inline Eigen::VectorXd arm6(const sensor_msgs::JointState& s)
{
  Eigen::VectorXd q(6);
  for (int i = 0; i < 6; ++i)
    q[i] = i < int(s.position.size()) ? s.position[i] : NAN;
  return q;
}

/// The scene's UR5e for FK of the TCP in the world.
struct SceneArm
{
  explicit SceneArm(const std::string& scene_name)
    : scene(vrrw_scene::loadScene(scene_name))
    , world(vrrw_kinematics::CollisionWorld::fromScene(scene))
    , state(vrrw_kinematics::initialState(world.model(), scene))
    , arm(world, *scene.robot("ur5e"))
  {
  }
  Eigen::Isometry3d tcp(const Eigen::VectorXd& q) { return arm.basePose(state) * arm.ikSolver().chain().fk(q); }
  vrrw_scene::Scene scene;
  vrrw_kinematics::CollisionWorld world;
  Eigen::VectorXd state;
  vrrw_kinematics::Arm arm;
};

/// Waits until `done` holds: the verdict is the condition; `bound` (wall clock) only keeps a broken node from
/// hanging the test, so it is generous (a loaded machine delays messages by tenths of a second, not by 10 s).
inline bool eventually(const std::function<bool()>& done, double bound = 10.0)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(bound); ros::WallTime::now() < end;
       ros::WallDuration(0.01).sleep())
    if (done())
      return true;
  return done();
}

template <class Service>
Service call(const std::string& name, Service srv = Service())
{
  EXPECT_TRUE(ros::service::waitForService(name, ros::Duration(20.0))) << name;
  std::string error;
  EXPECT_TRUE(vrrw_common::services().tryCall(name, srv, &error)) << error;
  return srv;
}
}  // namespace vrrw_interaction_test
