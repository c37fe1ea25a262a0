#pragma once
// The robots' controllers inside physics_node (pluginlib), each wired to its robot by joint indices.
#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/ros/robot_controller.h>

#include <pluginlib/class_loader.hpp>

#include <functional>
#include <string>
#include <vector>

namespace vrrw_physics
{
/// \brief One controller of class `plugin` per robot of the world, updated in the stepping thread before
/// every step. A robot whose controller fails to load or to initialize is named once and holds its targets.
class LoadedControllers
{
public:
  /// \brief Loads nothing when `plugin` is empty. `clock`: simulated time now, for the controllers' callbacks.
  LoadedControllers(PhysicsWorld& world, const vrrw_scene::Scene& scene, const std::string& plugin,
                    const std::function<ros::Time()>& clock);
  ~LoadedControllers();

  /// \brief Every controller reads its robot's state, updates and writes its drive targets for the step at
  /// the world's time. Returns one line per robot whose targets the drives refused (that robot keeps its last).
  std::vector<std::string> update(const ros::Duration& period);
  /// \brief true when no controller has a goal active.
  bool idle() const;
  void interrupt(const std::string& why);
  /// \brief "robot (class)" of every loaded controller.
  std::vector<std::string> describe() const;

private:
  struct Entry
  {
    std::string robot;
    pluginlib::UniquePtr<RobotController> controller;
    std::vector<std::size_t> joint;  ///< per controller joint: index in the robot's joints()
    std::vector<std::size_t> drive;  ///< per controller joint: its drive
    MeasuredJoints measured;
    DriveTargets targets;
  };
  void load(const vrrw_scene::Scene& scene, const std::string& robot, const std::function<ros::Time()>& clock);
  /// One controller's read, update and write at `now`; "" or the drives' refusal.
  std::string update(Entry& e, const ros::Time& now, const ros::Duration& period);

  PhysicsWorld& world_;
  std::string plugin_;
  pluginlib::ClassLoader<RobotController> loader_;  ///< outlives the instances it made
  std::vector<Entry> entries_;
};
}  // namespace vrrw_physics
