#pragma once
#include <Eigen/Dense>
#include <map>
#include <string>
#include <utility>
#include <vector>
#include <vrrw_kinematics/collision_world.h>
#include <vrrw_scene/scene.h>

#include <vrrw_interaction/gripper.h>

namespace vrrw_interaction
{
/// \brief Two bodies touching, as physics reports them (vrrw_physics/Contact).
struct BodyContact
{
  std::string body_a, body_b;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< world
  double normal_force = 0.0;                           ///< N
};

/// \brief Physics' rule: two of `gripper_links` press on `object` (kSqueezeForce or more each) at points on
/// opposite sides of `tcp`, i.e. the two fingers squeeze it (one finger resting on it, or the palm, does not).
bool fingersSqueeze(const std::string& object, const std::vector<BodyContact>& contacts,
                    const std::vector<std::string>& gripper_links, const Eigen::Vector3d& tcp);
constexpr double kSqueezeForce = 0.5;  ///< N: a finger's contact counts from this force on

/// \brief Fake mode's rule (no contact forces there): `robot`'s gripper is more than kClosedFraction closed and
/// its TCP within kTouchDistance of `object` at `state`.
bool closedGripperHolds(const vrrw_kinematics::CollisionWorld& world, const Eigen::VectorXd& state,
                        const vrrw_scene::Robot& robot, const GripperRange& gripper, const std::string& object);
constexpr double kClosedFraction = 0.3;
constexpr double kTouchDistance = 0.01;  ///< m

/// \brief The links below `link` in `model` (and it): a robot's gripper when `link` is its flange.
std::vector<std::string> linksBelow(const vrrw_kinematics::RobotModel& model, const std::string& link);

/// \brief What a person should hear of: kind "attach" or "detach" (as vrrw_msgs/Event) and one line.
struct HeldEvent
{
  std::string robot, kind, detail;
};

/// \brief The objects the grippers hold, attached to their TCP links in a collision world so that the ghost
/// carries them and plans keep them clear: attached on the first update where a rule holds, detached where it
/// is once the rule has not held for kLetGo s. The gripper's links may touch a held object; the fixed object it
/// rests on when taken (within kRestDistance: the table) may touch it until it has been lifted kLift, so a plan
/// from the grasp is not in collision and every later plan keeps it clear. ROS-free; not thread-safe.
class HeldObjects
{
public:
  static constexpr double kLetGo = 0.3;         ///< s without the rule before an object is let go
  static constexpr double kLift = 0.01;         ///< m
  static constexpr double kRestDistance = 0.005;  ///< m

  /// \brief For the robots of `scene` in `world` (both must outlive this).
  HeldObjects(vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene);

  /// \brief The links below the robot's flange, its gripper (empty without one).
  const std::vector<std::string>& gripperLinks(const std::string& robot) const;
  /// \brief The robot whose fingers squeeze `object` by fingersSqueeze at the live state, or "".
  std::string squeezedBy(const std::string& object, const std::vector<BodyContact>& contacts,
                         const Eigen::VectorXd& live) const;
  /// \brief The robot whose closed gripper holds `object` by closedGripperHolds, or "".
  std::string heldByClosedGripper(const std::string& object, const Eigen::VectorXd& live) const;

  /// \brief `holder` ("" nobody) holds `object` by the rule at time `now` (s): attach, keep, or detach after
  /// kLetGo; what happened. An object held by one robot stays its until that one lets go.
  std::vector<HeldEvent> update(const std::string& object, const std::string& holder, const Eigen::VectorXd& live,
                                double now);
  /// \brief Checks each held object against what it rested on again once lifted kLift from where it was taken.
  void releaseLifted(const Eigen::VectorXd& live);
  /// \brief While `allow`: every object `robot` holds may touch the scene object `surface`; false takes back
  /// exactly what true allowed.
  void allowPlaceContact(const std::string& robot, const std::string& surface, bool allow);
  /// \brief The robot holding `object`, or "".
  std::string holder(const std::string& object) const;

private:
  struct Held
  {
    std::string robot;
    std::vector<std::string> supports;  ///< fixed objects it may touch until lifted
    std::vector<std::string> restore;   ///< fixed objects the ACM let it touch while free (allowed again on release)
    Eigen::Vector3d taken_at = Eigen::Vector3d::Zero();  ///< the object's position when attached
    double last_seen = 0.0;                              ///< s: when the rule last held
  };
  HeldEvent attach(const std::string& object, const std::string& robot, const Eigen::VectorXd& live, double now);
  HeldEvent detach(const std::string& object, const Eigen::VectorXd& live);
  void releaseSupports(const std::string& object, Held& held, const Eigen::VectorXd& live, bool all);
  Eigen::Vector3d position(const std::string& object, const Eigen::VectorXd& live) const;

  vrrw_kinematics::CollisionWorld& world_;
  const vrrw_scene::Scene& scene_;
  std::map<std::string, Held> held_;                             ///< by object
  std::map<std::string, std::vector<std::string>> grippers_;      ///< by robot: its gripper's links
  std::map<std::string, GripperRange> ranges_;                   ///< by robot with a gripper
  std::vector<std::pair<std::string, std::string>> place_contacts_;  ///< pairs allowPlaceContact allowed
};
}  // namespace vrrw_interaction
