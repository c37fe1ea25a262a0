#pragma once
#include <vrrw_physics/operator_spring.h>

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>
#include <vector>

class btCollisionObject;
class btMultiBodyConstraint;
class btMultiBodyDynamicsWorld;

namespace vrrw_physics
{
class ArticulatedRobot;
class KinematicHand;
class RigidObject;

/// \brief What the operator does to the world: springs pulling links or objects (free-drive), tracked hands
/// (kinematic spheres that push by contact) and grasp assists (welds for scripted demos).
///
/// Every input is checked against the ranges of input_limits.h and refused whole with an InputError.
/// Hands are timed on the world's simulated clock: one not updated for `hand_timeout` s is removed, so a
/// lost tracker does not leave a solid sphere in the scene.
class OperatorInput
{
public:
  /// \brief Input to `world`, whose simulated time is `clock`; hands go after `hand_timeout` s (0: never).
  OperatorInput(btMultiBodyDynamicsWorld& world, const double& clock, double dt, double hand_timeout);
  ~OperatorInput();
  OperatorInput(const OperatorInput&) = delete;
  OperatorInput& operator=(const OperatorInput&) = delete;

  /// \brief Makes a robot's links reachable for springs and `tcp_link` its grasp-assist frame.
  void addRobot(ArticulatedRobot* robot, const std::string& name, const std::string& tcp_link);
  /// \brief Makes an object reachable for springs, grasp assists and contact names.
  void addObject(RigidObject* object);

  /// \brief Attaches (or replaces) spring `id` to a robot link or a movable object. Throws InputError.
  void attachSpring(const std::string& id, const OperatorSpring& spring);
  /// \brief Moves the target of spring `id`. Throws InputError.
  void moveSpring(const std::string& id, const Eigen::Isometry3d& target,
                  const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero());
  /// \brief Removes spring `id` (nothing when there is none).
  void releaseSpring(const std::string& id);
  /// \brief Ids of the attached springs.
  std::vector<std::string> springs() const;

  /// \brief Welds `object` to the robot's TCP link where it is now (on), or releases it (off).
  /// For scripted demos that must not drop anything; grasping by friction needs none. Throws InputError.
  void setGraspAssist(const std::string& robot, const std::string& object, bool on);
  /// \brief "robot/object" of every active grasp assist.
  std::vector<std::string> graspAssists() const;

  /// \brief Places hand `id` (a sphere of `radius` m, created on first use) at a world pose; radius 0 removes
  /// it. Throws InputError for a pose outside the world or a radius outside [0, kMaxHandRadius].
  void setHand(const std::string& id, const Eigen::Isometry3d& pose, double radius);
  /// \brief Removes hand `id` (nothing when there is none).
  void removeHand(const std::string& id);
  /// \brief Ids of the hands in the world.
  std::vector<std::string> hands() const;
  /// \brief "hand/<id>" for a hand's collision object, "" for any other.
  std::string handName(const btCollisionObject* object) const;

  /// \brief Before a step: removes hands not updated for hand_timeout, moves the others, applies the springs'
  /// wrenches. Returns one line per hand removed.
  std::vector<std::string> apply();
  /// \brief Releases every spring and hand (grasp assists stay).
  void releaseHandsAndSprings();
  /// \brief Releases every spring, hand and grasp assist.
  void releaseAll();

private:
  struct RobotRef
  {
    ArticulatedRobot* robot;
    std::string name;
    std::string tcp_link;
  };
  ArticulatedRobot* robotWithLink(const std::string& link) const;
  RigidObject* object(const std::string& name) const;
  void checkSpring(const std::string& id, const OperatorSpring& spring) const;
  void applySpring(const OperatorSpring& spring);

  btMultiBodyDynamicsWorld& world_;
  const double& clock_;
  double dt_;
  double hand_timeout_;
  std::vector<RobotRef> robots_;
  std::vector<RigidObject*> objects_;
  std::map<std::string, OperatorSpring> springs_;
  std::map<std::string, std::unique_ptr<btMultiBodyConstraint>> assists_;
  std::map<std::string, std::unique_ptr<KinematicHand>> hands_;
};
}  // namespace vrrw_physics
