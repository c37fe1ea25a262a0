#pragma once
#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/drive_mode.h>
#include <vrrw_physics/input_limits.h>
#include <vrrw_physics/operator_input.h>
#include <vrrw_physics/rigid_object.h>
#include <vrrw_physics/robot_drives.h>
#include <vrrw_physics/stable_pd.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vrrw_scene/scene.h>

class btBroadphaseInterface;
struct btOverlapFilterCallback;
class btCollisionDispatcher;
class btCollisionShape;
class btDefaultCollisionConfiguration;
class btMultiBodyConstraintSolver;
class btMultiBodyDynamicsWorld;
class btRigidBody;

namespace vrrw_physics
{
/// \brief How joint drives are made implicit.
enum class DriveScheme
{
  Constraint,  ///< one soft solver row per drive (JointDrive), solved together with contacts
  StablePd     ///< joint-space implicit PD per robot (StablePd) applied as torques; forces it does not
               ///< predict (contacts, pushes) meet a stiffness of only K*M/(M + h*(h*K + D))
};

/// \brief "constraint" or "stable_pd"; throws std::invalid_argument otherwise.
DriveScheme parseDriveScheme(const std::string& text);

/// \brief Simulation settings (PhysicsWorld refuses a dt that is not positive and negative timeouts).
struct WorldOptions
{
  DriveScheme drive_scheme = DriveScheme::Constraint;
  DriveMode mode = DriveMode::Rigid;  ///< every robot's arm at the start and after reset()
  double dt = 0.001;                  ///< fixed step (s)
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);
  int solver_iterations = 30;        ///< most Gauss-Seidel sweeps per step
  int solver_inner_iterations = 5;  ///< sweeps over joint rows (drives, couplings, limits) per sweep
                                     ///< while a robot link touches something (1 otherwise)
  double solver_residual = 1e-9;     ///< stop sweeping when the squared impulse change falls below
  bool joint_rows_last = true;       ///< each sweep solves the joint rows after the contacts, so the drives
                                     ///< see the velocities a step ends with (JointRowSolver; false: Bullet's
                                     ///< order, contacts last; ignored with bullet_reference)
  bool gravity_compensation = true;  ///< feed-forward torques cancelling gravity on each robot
  bool payload_compensation = true;  ///< with it, also the weight of what a robot holds (heldObjects())
  bool bullet_reference = false;     ///< true: stock Bullet (btMultiBodyDynamicsWorld and
                                     ///< btMultiBodyConstraintSolver, no broadphase filter), the reference
                                     ///< the default's MultiBodyWorld, JointRowSolver and SelfCollisionFilter
                                     ///< are tested against bit for bit (test_joint_row_solver)
  bool joint_space_dynamics = true;  ///< step robot velocities by qdd = M^-1 (tau - c) instead of Bullet's
                                     ///< articulated-body pass while a robot touches nothing
                                     ///< (MultiBodyWorld; equal up to rounding; ignored with bullet_reference)
  bool floor = true;                 ///< a static floor under z = 0 that objects (not robot links) land on
  double link_friction = 1.0;
  double max_joint_speed = 50.0;     ///< guard: rad/s or m/s
  double max_object_speed = 20.0;    ///< guard: m/s
  int snapshot_interval = 100;       ///< steps between last-good states
  int max_guard_trips = 3;           ///< guard trips with no good state between them before the world stops
  double target_timeout = 0.1;       ///< s of simulated time without drive targets before a robot holds
                                     ///< its last target positions at rest (0: never)
  double hand_timeout = 0.5;         ///< s of simulated time without a pose before a hand is removed (0: never)
};

/// \brief Joint names (prefixed), positions, velocities and efforts of one robot.
struct JointStates
{
  std::vector<std::string> name;
  std::vector<double> position;
  std::vector<double> velocity;
  std::vector<double> effort;
};

/// \brief Two bodies touching after the last step.
struct ContactPair
{
  std::string body_a;   ///< a robot link, an object or "hand/<id>"; body_a < body_b
  std::string body_b;
  double normal_force;  ///< N, summed over the pair's contact points
  Eigen::Vector3d position;  ///< world; the points' mean weighted by their force
};

/// \brief Joints, objects and drive targets at one time: what a guard trip or reset() puts back.
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
/// stepped at a fixed rate, with joint drives, operator input and a guard that rejects non-finite or
/// exploding steps.
///
/// The guard restores the last good state, releases the operator's springs and hands (the usual cause)
/// and reports once; after max_guard_trips trips with no good state between them the world stops
/// (step() returns false without stepping) until reset().
class PhysicsWorld
{
public:
  /// \brief Builds the world of a scene: robots from scene.urdf and scene.robots (initial positions, drive
  /// gains), objects from scene.objects. Throws std::runtime_error naming the robot, link, joint or object at
  /// fault, among them anything not finite or outside kWorldExtent.
  explicit PhysicsWorld(const vrrw_scene::Scene& scene, const WorldOptions& options = WorldOptions());
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// \brief Advances one fixed step. Returns false when the guard rejected it (lastError() says why) or
  /// the world has stopped.
  bool step();
  double time() const { return time_; }
  std::uint64_t steps() const { return steps_; }
  const WorldOptions& options() const { return options_; }
  const std::string& lastError() const { return last_error_; }
  /// \brief true after max_guard_trips trips in a row: nothing moves until reset().
  bool stopped() const { return stopped_; }
  /// \brief What happened since the last call that a person should hear of once: guard trips, robots whose
  /// targets stopped arriving, hands removed for silence.
  std::vector<std::string> takeReports();

  std::vector<std::string> robotNames() const;
  const ArticulatedRobot& robot(const std::string& name) const;
  JointStates jointStates(const std::string& robot) const;

  /// \brief Drive targets of a robot (RobotDrives::setTargets). Throws InputError.
  void setDriveTargets(const std::string& robot, const std::vector<std::string>& joints,
                       const std::vector<double>& positions, const std::vector<double>& velocities,
                       const std::vector<double>& efforts = {});
  /// \brief The same by drive index (drives()): a controller's targets every step. Throws InputError.
  void setDriveTargetsByIndex(const std::string& robot, const std::vector<std::size_t>& drives,
                       const std::vector<double>& positions, const std::vector<double>& velocities,
                       const std::vector<double>& efforts);
  /// \brief The drive index of each joint of a robot (RobotDrives::drives). Throws InputError.
  std::vector<std::size_t> drives(const std::string& robot, const std::vector<std::string>& joints) const;
  /// \brief Mode of the robot's arm joints; the arm holds where it is. Throws InputError.
  void setMode(const std::string& robot, DriveMode mode);
  DriveMode mode(const std::string& robot) const;
  /// \brief Custom gains (RobotDrives::setGains). Throws InputError.
  void setGains(const std::string& robot, const std::vector<std::string>& joints, const std::vector<double>& stiffness,
                const std::vector<double>& damping, const std::vector<double>& max_force);
  /// \brief Gains in effect for a joint. Throws InputError.
  DriveGains gains(const std::string& robot, const std::string& joint) const;
  void setGravityCompensation(const std::string& robot, bool on);
  /// \brief Objects the robot held between its fingers at the last step: touching two or more of its links and
  /// nothing else. Their weight joins the robot's gravity feed-forward (payload compensation, as a real arm
  /// holds its configured payload), at their centre of mass on the link that carries the fingers.
  std::vector<std::string> heldObjects(const std::string& robot) const;

  std::vector<std::string> objectNames() const;
  Eigen::Isometry3d objectPose(const std::string& object) const;
  /// \brief Teleports a movable object, at rest. Throws InputError (unknown or fixed object, pose outside
  /// the world).
  void setObjectPose(const std::string& object, const Eigen::Isometry3d& pose);
  /// \brief World pose of any robot link or object frame. Throws InputError.
  Eigen::Isometry3d framePose(const std::string& frame) const;

  /// \brief Springs, hands and grasp assists.
  OperatorInput& operatorInput() { return *operator_; }
  const OperatorInput& operatorInput() const { return *operator_; }

  /// \brief Pairs of bodies in contact after the last step.
  std::vector<ContactPair> contacts() const;

  WorldState snapshot() const;
  /// \brief Puts joints, objects, drive targets, time and step count back as they were in `state`.
  void restore(const WorldState& state);
  /// \brief Back to the start: initial state at time 0, the options' mode with the configured gains, gravity
  /// compensation as configured; no springs, hands, grasp assists or force limits from targets; not stopped.
  void reset();

  btMultiBodyDynamicsWorld* bulletWorld() const { return world_.get(); }

private:
  struct RobotEntry
  {
    vrrw_scene::Robot spec;
    std::unique_ptr<ArticulatedRobot> robot;
    std::unique_ptr<StablePd> stable_pd;
    std::unique_ptr<RobotDrives> drives;
    bool gravity_compensation = true;
    std::vector<PointLoad> held;             ///< objects held at the last step, as loads
    std::vector<std::string> held_objects;  ///< their names
  };

  void createBulletWorld();
  void addRobots(const vrrw_scene::Scene& scene);
  void addObjects(const vrrw_scene::Scene& scene);
  void addFloor();
  void checkExtent() const;
  void applyJointTorques();
  /// Finds what each robot holds after a step (held_loads.cpp).
  void findHeldObjects();
  RobotEntry& entry(const std::string& robot);
  const RobotEntry& entry(const std::string& robot) const;
  RigidObject& object(const std::string& name) const;
  bool robotInContact() const;
  /// "" when every joint and object is finite and within the guard's speeds, else the first that is not.
  std::string insaneState() const;
  void recoverFrom(const std::string& why);
  void restoreMotion(const WorldState& state);
  /// The Bullet world of the scene: robots at their initial state, objects, floor (construction and reset()).
  void build();
  /// Everything build() made, in the order Bullet needs.
  void tearDown();

  WorldOptions options_;
  vrrw_scene::Scene scene_;  ///< what build() builds
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btOverlapFilterCallback> self_collision_filter_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  std::vector<RobotEntry> robots_;
  std::vector<std::unique_ptr<RigidObject>> objects_;
  std::unique_ptr<btCollisionShape> floor_shape_;
  std::unique_ptr<btRigidBody> floor_;
  std::unique_ptr<OperatorInput> operator_;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  WorldState initial_;
  WorldState last_good_;
  std::string last_error_;
  int trips_in_a_row_ = 0;
  bool tripped_since_snapshot_ = false;
  bool stopped_ = false;
  std::vector<std::string> reports_;
};
}  // namespace vrrw_physics
