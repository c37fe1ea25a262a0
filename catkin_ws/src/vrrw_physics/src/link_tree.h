#pragma once
// A robot's URDF subtree as the rigid bodies of a Featherstone multibody: links joined by fixed joints
// merged into one body, each body's frame on its centre of mass and principal axes.
#include <urdf_model/model.h>

#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_scene/scene.h>

namespace vrrw_physics
{
/// \brief A collision shape of a merged body and the URDF link it came from.
struct CollisionPart
{
  vrrw_scene::Shape shape;  ///< origin in the body's root link frame
  std::string link;
};

/// \brief A rigid group of URDF links joined by fixed joints, rooted at one link.
struct MergedBody
{
  int parent = -1;  ///< index into the body list; -1 for the base
  urdf::JointConstSharedPtr joint;  ///< the movable joint into this body (none for the base)
  Eigen::Isometry3d parent_T_joint = Eigen::Isometry3d::Identity();  ///< in the parent's root link frame
  double mass = 0.0;
  Eigen::Vector3d mass_moment = Eigen::Vector3d::Zero();     ///< sum m_i c_i, root frame
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();  ///< about the root origin, root frame
  std::vector<CollisionPart> parts;
  std::vector<std::pair<std::string, Eigen::Isometry3d>> links;  ///< root_T_link
  Eigen::Isometry3d root_T_frame = Eigen::Isometry3d::Identity();  ///< Bullet frame: COM, principal axes
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();             ///< principal moments of inertia
};

/// \brief The bodies of the subtree of `base_link`, parents before children (the base first), with their
/// Bullet frames. A body without mass gets 1 g (Bullet needs a positive mass on every link). Throws
/// std::runtime_error naming the robot and the link or joint (unsupported joint type, unreadable
/// collision mesh, inertia that is not finite).
std::vector<MergedBody> mergeFixedLinks(const urdf::ModelInterface& model, const std::string& base_link,
                                        const std::string& robot);

/// \brief World pose of a link from the joint origins above it (every joint at zero).
Eigen::Isometry3d worldPose(const urdf::ModelInterface& model, const std::string& link);
}  // namespace vrrw_physics
