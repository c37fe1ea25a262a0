#pragma once
#include <vrrw_physics/joint_drive.h>
#include <vrrw_physics/joint_limits.h>
#include <vrrw_physics/joint_row_group.h>
#include <vrrw_physics/joint_space_inertia.h>

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <LinearMath/btScalar.h>
#include <urdf_model/model.h>

class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyLinkCollider;
class btCollisionShape;

namespace vrrw_physics
{
struct MergedBody;

/// \brief Contact material of every link of a robot.
struct LinkMaterial
{
  double friction = 1.0;
  double restitution = 0.0;
};

/// \brief A movable URDF joint as simulated.
struct SimJoint
{
  std::string name;
  int link = -1;              ///< Bullet link index of its child
  bool prismatic = false;
  bool limited = false;
  double lower = 0.0;
  double upper = 0.0;
  double max_effort = 0.0;    ///< from the URDF, 0 when absent
  double max_velocity = 0.0;  ///< from the URDF, 0 when absent
  int drive = -1;             ///< index into drives(), -1 for a mimic joint
  int mimic = -1;             ///< index in joints() of the joint it mimics, -1 when none
  int mimic_drive = -1;       ///< index of its follower drive (constraint scheme), -1 when none
  double multiplier = 1.0;    ///< q = multiplier * q_master + offset
  double offset = 0.0;
};

/// \brief A point mass carried by a Bullet link of a robot (an object it holds), for gravityTorques().
struct PointLoad
{
  int body = -1;  ///< Bullet link index; -1 (the fixed base) loads no joint
  double mass = 0.0;  ///< kg
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< world position of its centre of mass
};

/// \brief One robot as a single Featherstone btMultiBody built from a URDF subtree.
///
/// Links joined by fixed joints are merged (mass, inertia, collision shapes); every movable joint
/// (revolute, continuous, prismatic) becomes a Bullet link whose frame sits at its centre of mass on
/// the principal axes of inertia. Non-mimic joints get a JointDrive, mimic joints a JointCoupling
/// plus a follower drive that copies the master's gains and (mapped) target, so every finger link is
/// pushed by its own drive and the solver need not carry the grip force through the coupling chain;
/// limited joints share one JointLimits; every Bullet link gets a collider (links without
/// collision geometry get one that collides with nothing, so its constraints are solved).
/// Featherstone, "Rigid Body Dynamics Algorithms", 2008.
class ArticulatedRobot
{
public:
  /// \brief Builds the subtree of `base_link` of `model`, its base fixed at the base link's world pose
  /// (chained through the joints above it). Throws std::runtime_error naming the link or joint.
  ArticulatedRobot(const urdf::ModelInterface& model, const std::string& name, const std::string& base_link,
                   const LinkMaterial& material = LinkMaterial());
  ~ArticulatedRobot();
  ArticulatedRobot(const ArticulatedRobot&) = delete;
  ArticulatedRobot& operator=(const ArticulatedRobot&) = delete;

  /// \brief Adds body, colliders, couplings, limits and (when `drive_constraints`) the drive
  /// constraints to `world` (once); removed again by the destructor.
  void addToWorld(btMultiBodyDynamicsWorld* world, bool drive_constraints = true);

  const std::string& name() const { return name_; }
  btMultiBody* body() const { return body_.get(); }
  /// \brief M^-1 of the last updateDynamics (invalid after setState until the next one).
  const JointSpaceResponse& response() const { return response_; }
  /// \brief Every movable joint, depth-first from the base (mimic joints included).
  const std::vector<SimJoint>& joints() const { return joints_; }
  /// \brief Index in joints() of a joint name, -1 when unknown.
  int jointIndex(const std::string& joint) const;
  std::vector<std::unique_ptr<JointDrive>>& drives() { return drives_; }
  const std::vector<std::unique_ptr<JointDrive>>& drives() const { return drives_; }

  std::vector<double> positions() const;
  std::vector<double> velocities() const;
  /// \brief Joint efforts of the last step: drive (or coupling) force plus feed-forward torque.
  std::vector<double> efforts(double dt) const;
  /// \brief Copies each master drive's gains and mapped target to its mimic joints' follower drives.
  void followMasters();
  /// \brief Positions of every joint from those of the non-mimic joints (mimic entries are recomputed).
  std::vector<double> withMimics(std::vector<double> positions) const;
  /// \brief Sets positions and velocities of every joint (order of joints()) and refreshes frames.
  void setState(const std::vector<double>& positions, const std::vector<double>& velocities);

  bool hasLink(const std::string& link) const { return links_.count(link) > 0; }
  /// \brief World pose of a URDF link (merged links included); throws for an unknown link.
  Eigen::Isometry3d linkPose(const std::string& link) const;
  /// \brief Bullet link index carrying a URDF link (-1: the base); throws for an unknown link.
  int bulletLink(const std::string& link) const { return linkFrame(link).body; }
  /// \brief World velocity of a point given in a link's frame.
  Eigen::Vector3d pointVelocity(const std::string& link, const Eigen::Vector3d& point) const;
  /// \brief World angular velocity of a link.
  Eigen::Vector3d angularVelocity(const std::string& link) const;
  /// \brief Applies a world force at a point given in a link's frame plus a world torque (for this step).
  void applyWrench(const std::string& link, const Eigen::Vector3d& point, const Eigen::Vector3d& force,
                   const Eigen::Vector3d& torque);

  /// \brief Generalized gravity force on each joint (order of joints()) in the current configuration, of the
  /// robot's links and of `loads` it carries.
  std::vector<double> gravityTorques(const Eigen::Vector3d& gravity, const std::vector<PointLoad>& loads = {}) const;
  /// \brief The Bullet link nearest the base that is an ancestor of (or is) every link of `bodies` (-1: the base).
  int commonAncestor(const std::vector<int>& bodies) const;
  /// \brief Joint torques added for this step so far (feed-forward, drives applied as torques).
  const std::vector<double>& appliedTorques() const { return feed_forward_; }
  /// \brief Adds a joint torque for this step (reported by efforts()).
  void addJointTorque(std::size_t joint, double torque);
  /// \brief World pose of a Bullet link frame (COM, principal axes); -1 for the base
  /// (as of the last refreshFrames()).
  const Eigen::Isometry3d& bodyPose(int body) const { return poses_[std::size_t(body + 1)]; }
  /// \brief Every bodyPose, the base first.
  const std::vector<Eigen::Isometry3d>& framePoses() const { return poses_; }
  /// \brief The URDF link of child shape `shape` of Bullet link `body`'s collider (-1: the base); the
  /// body's first link for a shape it does not have (a link without collision geometry).
  const std::string& shapeLink(int body, int shape) const;
  /// \brief Re-reads link frames from Bullet (after a step); setState() does it too.
  void refreshFrames();
  /// \brief The joint-space inertia M of the configuration (as of refreshFrames()), whose inverse
  /// the robot's solver rows use this step. Returns M.
  const JointMatrix& updateDynamics();
  /// \brief Forgets the feed-forward torques reported by efforts() (Bullet clears applied torques each step).
  void clearFeedForward();

private:
  void createMultiBody(const std::vector<MergedBody>& bodies, const Eigen::Isometry3d& base_pose);
  void setupLink(int link, const MergedBody& body, const MergedBody& parent);
  void createColliders(const std::vector<MergedBody>& bodies, const LinkMaterial& material);
  /// The body's collision shapes as one compound (owned by shapes_); a tiny sphere for a body without any.
  btCollisionShape* compoundShape(const MergedBody& body);
  void createJointRows(const urdf::ModelInterface& model);
  void addCoupling(std::size_t joint, const urdf::JointMimic& mimic);

  /// The URDF links of a collider: its body's first link, and the link of each child shape.
  struct ShapeLinks
  {
    std::string body_link;
    std::vector<std::string> shapes;
  };
  struct LinkFrame
  {
    int body = -1;  ///< -1 for the base
    Eigen::Isometry3d body_T_link = Eigen::Isometry3d::Identity();
  };
  const LinkFrame& linkFrame(const std::string& link) const;
  /// One value per joint (order of joints()) read from Bullet: getJointPos, getJointVel.
  std::vector<double> jointValues(btScalar (btMultiBody::*value)(int) const) const;
  /// World angular and linear (COM) velocity of a Bullet link.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> bodyVelocity(int body) const;

  std::string name_;
  std::unique_ptr<btMultiBody> body_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::vector<std::unique_ptr<JointDrive>> drives_;
  std::vector<std::unique_ptr<JointCoupling>> couplings_;
  std::vector<std::unique_ptr<JointDrive>> mimic_drives_;
  std::unique_ptr<JointLimits> limits_;
  std::unique_ptr<JointRowGroup> rows_;  ///< what Bullet sees of the above
  std::vector<SimJoint> joints_;
  std::vector<double> feed_forward_;
  std::vector<int> coupling_of_joint_;
  std::map<std::string, LinkFrame> links_;
  std::vector<ShapeLinks> shape_links_;  ///< per collider, the base first
  std::vector<Eigen::Isometry3d> poses_;
  JointMatrix inertia_;
  JointSpaceResponse response_;
  btMultiBodyDynamicsWorld* world_ = nullptr;
  bool drive_constraints_ = true;
};
}  // namespace vrrw_physics
