#pragma once
// The controller of a simulated robot as physics_node loads it (pluginlib, base class
// "vrrw_physics::RobotController"), the way gazebo_ros_control loads a RobotHWSim: it runs in the
// stepping thread, so step k waits for every controller's answer to step k by construction.
#include <functional>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <ros/time.h>
#include <vrrw_scene/scene.h>

namespace vrrw_physics
{
/// \brief What a controller sees of its simulated robot at the start of a step: its joints (the order of
/// RobotController::joints()), measured.
struct MeasuredJoints
{
  std::vector<double> position, velocity;
  std::vector<double> effort;  ///< drive force plus feed-forward of the last step (N m or N)
};

/// \brief What a controller commands for the step: drive targets of its joints (same order).
struct DriveTargets
{
  std::vector<double> position, velocity;
  std::vector<double> force_limit;  ///< N m or N while these targets hold; 0: the configured limit
};

/// \brief A simulated robot's controller. physics_node calls, for every robot and every step, in one thread:
/// update() (the controller's read, update and write) and then the world's step. Its ROS callbacks (action
/// goals, topics) run in the same thread between steps, so a goal takes effect at a step boundary: at once
/// while the simulation waits (paused), at its trajectory's header.stamp when that lies ahead.
class RobotController
{
public:
  virtual ~RobotController() = default;

  /// \brief Called once. `nh`: the robot's namespace (/<robot>); `scene`: the scene physics simulates;
  /// `clock`: simulated time now (between steps: the time of the next one). Throws std::exception naming
  /// what is wrong (the robot then has no controller and holds its targets).
  virtual void initialize(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, const std::string& robot,
                          std::function<ros::Time()> clock) = 0;
  /// \brief The joints it measures and commands (prefixed names, driven joints of the robot), after initialize.
  virtual std::vector<std::string> joints() const = 0;
  /// \brief One step at simulated `time`: reads `measured`, updates, writes every entry of `targets`.
  virtual void update(const ros::Time& time, const ros::Duration& period, const MeasuredJoints& measured,
                      DriveTargets& targets) = 0;
  /// \brief true while nothing runs that a client would wait for (no goal active).
  virtual bool idle() const = 0;
  /// \brief The simulation jumped (reset) or stopped (its guard), `why`: running goals end; the next update
  /// holds what is measured then.
  virtual void interrupt(const std::string& why) = 0;
};
}  // namespace vrrw_physics
