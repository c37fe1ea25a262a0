#pragma once
#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/drive_gains.h>
#include <vrrw_physics/operator_spring.h>
#include <vrrw_physics/rigid_object.h>
#include <vrrw_physics/stable_pd.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vrrw_scene/scene.h>

class btBroadphaseInterface;
struct btOverlapFilterCallback;
class btCollisionDispatcher;
class btDefaultCollisionConfiguration;
class btMultiBodyConstraintSolver;
class btMultiBodyDynamicsWorld;
class btRigidBody;
class btCollisionShape;
class btMultiBodyConstraint;
struct btDefaultMotionState;

namespace vrrw_physics
{
/// \brief Bad input to the world (unknown robot/joint/link, NaN, negative gains, wrong lengths);
/// what() is one line naming the thing. The world is unchanged.
class InputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// \brief How joint drives are made implicit.
enum class DriveScheme
{
  Constraint,  ///< one soft solver row per drive (JointDrive), solved together with contacts
  StablePd     ///< joint-space implicit PD per robot (StablePd) applied as torques; forces it does not
               ///< predict (contacts, pushes) meet a stiffness of only K*M/(M + h*(h*K + D))
};

/// \brief Simulation settings.
struct WorldOptions
{
  DriveScheme drive_scheme = DriveScheme::Constraint;
  double dt = 0.001;                                    ///< fixed step (s)
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);
  int solver_iterations = 30;        ///< most Gauss-Seidel sweeps per step
  int solver_inner_iterations = 5;  ///< sweeps over joint rows (drives, couplings, limits) per sweep
                                     ///< while a robot link touches something (1 otherwise)
  double solver_residual = 1e-9;     ///< stop sweeping when the squared impulse change falls below
  bool gravity_compensation = true;  ///< feed-forward torques cancelling gravity on each robot
  bool bullet_reference = false;     ///< true: stock Bullet (btMultiBodyDynamicsWorld and
                                     ///< btMultiBodyConstraintSolver, no broadphase filter), the reference
                                     ///< the default's MultiBodyWorld, JointRowSolver and SelfCollisionFilter
                                     ///< are tested against bit for bit (test_joint_row_solver)
  bool joint_space_dynamics = true;  ///< step robot velocities by qdd = M^-1 (tau - c) instead of Bullet's
                                     ///< articulated-body pass while a robot touches nothing
                                     ///< (MultiBodyWorld; equal up to rounding; ignored with bullet_reference)
  double link_friction = 1.0;
  double max_joint_speed = 50.0;     ///< guard: rad/s or m/s
  double max_object_speed = 20.0;    ///< guard: m/s
  int snapshot_interval = 100;       ///< steps between last-good states
};

/// \brief Joint names (prefixed), positions, velocities and efforts of one robot.
struct JointStates
{
  std::vector<std::string> name;
  std::vector<double> position;
  std::vector<double> velocity;
  std::vector<double> effort;
};

/// \brief Everything needed to put the world back: joints, objects, drive targets, time.
struct WorldState
{
  double time = 0.0;
  std::uint64_t steps = 0;
  std::vector<std::vector<double>> positions, velocities;
  std::vector<std::vector<double>> target_positions, target_velocities;
  std::vector<Eigen::Isometry3d> object_poses;
  std::vector<Eigen::Vector3d> object_linear, object_angular;
};

/// \brief Every robot (one Featherstone multibody each) and object of a scene in one Bullet world,
/// stepped at a fixed rate, with joint drives, operator springs, a kinematic hand and a guard that
/// rejects non-finite or exploding steps.
class PhysicsWorld
{
public:
  /// \brief Builds the world of a scene: robots from scene.urdf and scene.robots (initial positions,
  /// drive gains from each robot's config file and its gripper's), objects from scene.objects.
  /// Throws std::runtime_error naming the robot, link, joint, object or file at fault.
  explicit PhysicsWorld(const vrrw_scene::Scene& scene, const WorldOptions& options = WorldOptions());
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// \brief Advances one fixed step. Returns false when the guard rejected it: the last good state
  /// is restored and lastError() says why.
  bool step();
  double time() const { return time_; }
  std::uint64_t steps() const { return steps_; }
  const WorldOptions& options() const { return options_; }
  const std::string& lastError() const { return last_error_; }

  std::vector<std::string> robotNames() const;
  const ArticulatedRobot& robot(const std::string& name) const;
  JointStates jointStates(const std::string& robot) const;

  /// \brief Drive targets by prefixed joint name; velocities empty means zero. Throws InputError.
  void setDriveTargets(const std::string& robot, const std::vector<std::string>& joints,
                       const std::vector<double>& positions, const std::vector<double>& velocities);
  /// \brief Mode of the robot's arm joints (gripper joints keep their rigid gains). Throws InputError.
  void setMode(const std::string& robot, DriveMode mode);
  DriveMode mode(const std::string& robot) const;
  /// \brief Custom gains (the robot switches to Custom) for the listed joints, or, with `joints`
  /// empty, for the arm joints in order. max_force empty keeps the limits. Throws InputError.
  void setGains(const std::string& robot, const std::vector<std::string>& joints, const std::vector<double>& stiffness,
                const std::vector<double>& damping, const std::vector<double>& max_force);
  /// \brief Gains in effect for a joint. Throws InputError.
  DriveGains gains(const std::string& robot, const std::string& joint) const;
  void setGravityCompensation(const std::string& robot, bool on);

  std::vector<std::string> objectNames() const;
  Eigen::Isometry3d objectPose(const std::string& object) const;
  /// \brief Teleports an object (operator tool, not used for grasping). Throws InputError.
  void setObjectPose(const std::string& object, const Eigen::Isometry3d& pose);
  /// \brief World pose of any robot link or object frame. Throws InputError.
  Eigen::Isometry3d framePose(const std::string& frame) const;

  /// \brief Attaches (or replaces) operator spring `id` to a robot link or object. Throws InputError.
  void attachSpring(const std::string& id, const OperatorSpring& spring);
  /// \brief Moves the target of spring `id`. Throws InputError.
  void moveSpring(const std::string& id, const Eigen::Isometry3d& target,
                  const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero());
  void releaseSpring(const std::string& id);

  /// \brief Grasp assist (off unless asked for): welds `object` to the robot's TCP link where it is
  /// now, or releases it. For scripted demos that must not drop anything; grasping tests run without.
  void setGraspAssist(const std::string& robot, const std::string& object, bool on);
  /// \brief "robot/object" of every active grasp assist.
  std::vector<std::string> graspAssists() const;

  /// \brief Places the kinematic hand (a sphere that pushes links and objects by contact); it is
  /// created on first use and moves with the velocity implied by successive poses.
  void setHandPose(const Eigen::Isometry3d& pose, double radius = 0.04);
  void removeHand();

  WorldState snapshot() const;
  void restore(const WorldState& state);
  /// \brief Back to the initial state of the scene (time 0).
  void reset();

  btMultiBodyDynamicsWorld* bulletWorld() const { return world_.get(); }

private:
  struct RobotEntry
  {
    vrrw_scene::Robot spec;
    std::unique_ptr<ArticulatedRobot> robot;
    std::unique_ptr<StablePd> stable_pd;
    DriveGainTable table;
    DriveMode mode = DriveMode::Rigid;
    std::vector<bool> arm_joint;  ///< per joint of robot->joints()
    bool gravity_compensation = true;
  };
  struct SpringEntry
  {
    std::string id;
    OperatorSpring spring;
  };

  RobotEntry& entry(const std::string& robot);
  const RobotEntry& entry(const std::string& robot) const;
  RigidObject& object(const std::string& name) const;
  void applyMode(RobotEntry& e);
  void applySprings();
  bool stateIsSane();
  bool robotInContact() const;
  bool frameExists(const std::string& frame) const;

  WorldOptions options_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btOverlapFilterCallback> self_collision_filter_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  std::vector<RobotEntry> robots_;
  std::vector<std::unique_ptr<RigidObject>> objects_;
  std::vector<SpringEntry> springs_;
  std::map<std::string, std::unique_ptr<btMultiBodyConstraint>> assists_;
  std::unique_ptr<btCollisionShape> hand_shape_;
  std::unique_ptr<btDefaultMotionState> hand_motion_;
  std::unique_ptr<btRigidBody> hand_;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  WorldState initial_;
  WorldState last_good_;
  std::string last_error_;
};
}  // namespace vrrw_physics
