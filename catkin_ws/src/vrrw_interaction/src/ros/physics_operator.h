#pragma once
#include <Eigen/Geometry>
#include <ros/ros.h>
#include <string>
#include <vrrw_interaction/ghost_robot.h>

namespace vrrw_interaction
{
/// \brief Gains of a grip's operator spring. The defaults are physics' recommended ones (vrrw_physics
/// OperatorSpring: the wrist follows a hand at 0.2 m/s within 1.3 cm RMS); the angular pair holds a gripped
/// link's orientation (README: the wrist within 2 deg over the drag benchmark; 0, 0 leaves it free).
struct SpringGains
{
  double stiffness = 5000.0;  ///< N/m
  double damping = 100.0;     ///< N s/m
  double max_force = 200.0;   ///< N, and N m for the torque
  double angular_stiffness = 500.0;  ///< N m/rad
  double angular_damping = 5.0;      ///< N m s/rad
};

/// \brief The physics node's operator interface as free-drive uses it: drive modes (/physics/set_mode),
/// springs (/physics/set_spring, /physics/spring_target) and the open hand's sphere (/physics/hand). Service
/// calls wait for the physics node: never call them holding the world's mutex. Thread-safe.
class PhysicsOperator
{
public:
  explicit PhysicsOperator(const SpringGains& gains);

  /// \brief The robot's arm drives compliant (free-drive) or rigid (holding the pose it is in).
  Outcome setMode(const std::string& robot, bool compliant);
  /// \brief Spring `id` pulls `point` (in `body`'s frame) to `target`; with `angular` also the body's
  /// orientation to target's rotation. False (and a warning) when physics refused it.
  bool attach(const std::string& id, const std::string& body, const Eigen::Vector3d& point,
              const Eigen::Isometry3d& target, bool angular);
  void release(const std::string& id, const std::string& body);
  /// \brief Moves spring `id`'s target (a topic: no waiting) at simulated time `stamp` (physics applies it at the
  /// first step at or after it; zero or past: before the next step). A stamp more than a second ahead of ROS time
  /// (a tracker on a clock of its own) is sent as zero, so physics never holds it back for long.
  void moveTarget(const std::string& id, const Eigen::Isometry3d& target, const ros::Time& stamp = ros::Time());
  /// \brief Hand `id` as a pushing sphere of `radius` at `pose` (0: none), at `stamp` as moveTarget's.
  void hand(const std::string& id, const Eigen::Isometry3d& pose, double radius, const ros::Time& stamp);

private:
  /// The stamp physics gets: `stamp`, or zero (at once) when it is more than a second ahead of ROS time.
  static ros::Time applied(const ros::Time& stamp);
  SpringGains gains_;
  ros::Publisher spring_target_, hand_;
};
}  // namespace vrrw_interaction
