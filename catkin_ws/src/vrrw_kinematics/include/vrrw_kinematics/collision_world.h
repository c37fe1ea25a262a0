#pragma once
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>
#include <vrrw_scene/scene.h>

#include <vrrw_kinematics/allowed_collision_matrix.h>
#include <vrrw_kinematics/contact.h>
#include <vrrw_kinematics/robot_model.h>

namespace fcl
{
template <typename S>
class CollisionGeometry;
}

namespace vrrw_kinematics
{
/// \brief One FCL primitive of a body, placed in the body frame.
struct CollisionElement
{
  int body = -1;
  std::shared_ptr<fcl::CollisionGeometry<double>> geometry;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  vrrw_scene::Shape::Type type = vrrw_scene::Shape::Type::Sphere;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  ///< box half sizes; cylinder (r, r, half length)
  double bounding_radius = 0.0;                           ///< about the element origin
};

/// \brief A link with collision geometry, a free scene object, or an object attached to a link.
struct CollisionBody
{
  std::string name;
  std::string robot;  ///< owning robot; "" for scene objects
  int link = -1;      ///< model link the body moves with; -1 for a free object
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();  ///< free object: world pose; attached: in the link frame
  bool object = false;
  std::vector<int> elements;
};

/// \brief Smallest distance between any pair that is checked (negative or zero when touching).
struct DistanceReport
{
  double distance = std::numeric_limits<double>::infinity();
  std::string body_a;
  std::string body_b;
};

/// \brief FCL collision world of a scene: every robot link with URDF collision geometry, the scene
/// objects, attached objects, and an allowed-collision matrix computed as MoveIt's setup assistant does.
class CollisionWorld
{
public:
  /// \brief `robot_names` (scene robot names, the link prefixes) tell which robot a link belongs to.
  CollisionWorld(const std::string& urdf, const std::vector<vrrw_scene::Object>& objects = {},
                 const std::vector<std::string>& robot_names = {});
  /// \brief World of a loaded scene: its combined URDF, its robots and its objects.
  static CollisionWorld fromScene(const vrrw_scene::Scene& scene);

  const RobotModel& model() const { return model_; }
  const std::vector<CollisionBody>& bodies() const { return bodies_; }
  const std::vector<CollisionElement>& elements() const { return elements_; }
  /// \brief Body index by name, -1 when there is none.
  int bodyIndex(const std::string& name) const;
  const AllowedCollisionMatrix& acm() const { return acm_; }
  /// \brief Allows a pair (reason "user") or forbids it again.
  void setAllowed(const std::string& a, const std::string& b, bool allowed);

  /// \brief Adjacent links, plus pairs never or always in collision over `samples` uniform random states
  /// drawn with `seed`. "Never" applies within one robot only, and to pairs more than two joint variables
  /// apart only when their bounding boxes never came within 2 cm (sparse samples; a near miss stays
  /// checked); "always" across robots and objects only
  /// when both bodies are fixed in the world (a base on its table), so a movable link is always checked
  /// against other robots and objects.
  void computeAllowedCollisions(int samples = 10000, std::uint64_t seed = 1);
  /// \brief Like computeAllowedCollisions, but reuses `<cache_dir>/acm_<key>.txt` when its content key
  /// matches; returns true when the cache was used.
  bool loadOrComputeAllowedCollisions(const std::string& cache_dir, int samples = 10000, std::uint64_t seed = 1);
  /// \brief Hash of the URDF, objects, attachments and sampling parameters.
  std::string contentKey(int samples, std::uint64_t seed) const;

  /// \brief World pose of every body for the model's variable vector.
  void bodyTransforms(const Eigen::VectorXd& variables, std::vector<Eigen::Isometry3d>& out) const;
  /// \brief Full-scene check of every pair not allowed (only pairs with a body of `robot` when given).
  Contact check(const Eigen::VectorXd& variables, const std::string& robot = "") const;
  /// \brief Smallest distance over every pair not allowed, except pairs of two bodies fixed in the world
  /// (a base on its table); only pairs with `owner` (a body name or a robot name) when it is given.
  /// Throws KinematicsError(UnknownLink) when `owner` is neither.
  DistanceReport distance(const Eigen::VectorXd& variables, const std::string& owner = "") const;

  /// \brief Moves a free object; throws KinematicsError(InvalidArgument) for an unknown object.
  void setObjectPose(const std::string& object, const Eigen::Isometry3d& pose);
  /// \brief Fixes `object` to `link` at its current relative pose; it may touch `touch_links`.
  void attachObject(const std::string& object, const std::string& link, const Eigen::VectorXd& variables,
                    const std::vector<std::string>& touch_links);
  /// \brief Frees an attached object where it is now.
  void detachObject(const std::string& object, const Eigen::VectorXd& variables);

  /// \brief Element pairs whose bodies are not allowed to touch (kept in sync with the ACM).
  const std::vector<std::pair<int, int>>& checkedPairs() const { return pairs_; }
  /// \brief Counts changes of the world (an object moved, attached or detached, allowed pairs changed): a
  /// StateChecker built at an older revision is out of date.
  std::uint64_t revision() const { return revision_; }

private:
  void addBody(CollisionBody body, const std::vector<vrrw_scene::Shape>& shapes);
  void rebuildPairs();
  std::string robotOf(const std::string& link) const;
  /// \brief True for a free object or a link with no movable joint between it and the root.
  bool fixedInWorld(const CollisionBody& body) const;

  RobotModel model_;
  std::vector<std::string> robot_names_;
  std::vector<CollisionBody> bodies_;
  std::vector<CollisionElement> elements_;
  AllowedCollisionMatrix acm_;
  std::vector<std::pair<int, int>> pairs_;
  std::string urdf_;
  std::uint64_t revision_ = 0;
};

/// \brief World-frame axis-aligned box (centre, half extents) of an element at `pose`.
void elementAabb(const CollisionElement& element, const Eigen::Isometry3d& pose, Eigen::Vector3d& center,
                 Eigen::Vector3d& half);
/// \brief Exact FCL test of two elements at their world poses.
bool elementsCollide(const CollisionElement& a, const Eigen::Isometry3d& pose_a, const CollisionElement& b,
                     const Eigen::Isometry3d& pose_b);
}  // namespace vrrw_kinematics
