#include "link_tree.h"

#include <Eigen/Eigenvalues>
#include <stdexcept>

#include <vrrw_scene/urdf_geometry.h>

namespace vrrw_physics
{
namespace
{
using vrrw_scene::toIsometry;

bool isMovable(const urdf::Joint& joint)
{
  return joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS ||
         joint.type == urdf::Joint::PRISMATIC;
}

void addInertial(const urdf::Inertial& in, const Eigen::Isometry3d& root_T_link, MergedBody& b)
{
  const Eigen::Isometry3d root_T_com = root_T_link * toIsometry(in.origin);
  Eigen::Matrix3d local;
  local << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Eigen::Matrix3d r = root_T_com.rotation();
  const Eigen::Vector3d c = root_T_com.translation();
  b.mass += in.mass;
  b.mass_moment += in.mass * c;
  b.inertia_origin +=
      r * local * r.transpose() + in.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
}

void addCollisions(const urdf::Link& link, const Eigen::Isometry3d& root_T_link, const std::string& robot,
                   MergedBody& b)
{
  for (const auto& collision : link.collision_array)
  {
    if (!collision || !collision->geometry)
      continue;
    try
    {
      b.parts.push_back(
          { vrrw_scene::shapeFromUrdf(*collision->geometry, root_T_link * toIsometry(collision->origin)), link.name });
    }
    catch (const std::runtime_error& e)
    {
      throw std::runtime_error("robot " + robot + ": link " + link.name + ": collision " + e.what());
    }
  }
}

/// Adds `link` to body `body` and walks on: a fixed joint merges its child into the same body, a movable
/// joint starts a new one.
void addLink(const urdf::ModelInterface& model, const urdf::LinkConstSharedPtr& link, int body,
             const Eigen::Isometry3d& root_T_link, const std::string& robot, std::vector<MergedBody>& bodies)
{
  bodies[std::size_t(body)].links.emplace_back(link->name, root_T_link);
  if (link->inertial && link->inertial->mass > 0.0)
    addInertial(*link->inertial, root_T_link, bodies[std::size_t(body)]);
  addCollisions(*link, root_T_link, robot, bodies[std::size_t(body)]);
  for (const auto& joint : link->child_joints)
  {
    const urdf::LinkConstSharedPtr child = model.getLink(joint->child_link_name);
    if (!child)
      throw std::runtime_error("joint " + joint->name + ": child link '" + joint->child_link_name + "' missing");
    const Eigen::Isometry3d origin = root_T_link * toIsometry(joint->parent_to_joint_origin_transform);
    if (!isMovable(*joint))
    {
      if (joint->type != urdf::Joint::FIXED)
        throw std::runtime_error("joint " + joint->name +
                                 ": type not supported (fixed, revolute, continuous, prismatic)");
      addLink(model, child, body, origin, robot, bodies);
      continue;
    }
    MergedBody next;
    next.parent = body;
    next.joint = joint;
    next.parent_T_joint = origin;
    bodies.push_back(next);
    addLink(model, child, int(bodies.size()) - 1, Eigen::Isometry3d::Identity(), robot, bodies);
  }
}

/// The body's Bullet frame: its centre of mass on the principal axes of inertia.
void computeFrame(MergedBody& b, const std::string& robot)
{
  if (b.mass <= 0.0)
  {
    b.mass = 1e-3;
    b.inertia_origin = 1e-7 * Eigen::Matrix3d::Identity();
    if (b.joint)
      b.mass_moment.setZero();
  }
  const Eigen::Vector3d com = b.mass_moment / b.mass;
  const Eigen::Matrix3d inertia =
      b.inertia_origin - b.mass * (com.squaredNorm() * Eigen::Matrix3d::Identity() - com * com.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (inertia + inertia.transpose()));
  Eigen::Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0)
    axes.col(2) = -axes.col(2);
  b.principal = eig.eigenvalues().cwiseMax(1e-9);
  b.root_T_frame = Eigen::Isometry3d::Identity();
  b.root_T_frame.translate(com);
  b.root_T_frame.rotate(axes);
  if (!b.principal.allFinite() || !com.allFinite())
    throw std::runtime_error("robot " + robot + ": link " + b.links.front().first + ": inertia is not finite");
}
}  // namespace

std::vector<MergedBody> mergeFixedLinks(const urdf::ModelInterface& model, const std::string& base_link,
                                        const std::string& robot)
{
  const urdf::LinkConstSharedPtr base = model.getLink(base_link);
  if (!base)
    throw std::runtime_error("robot " + robot + ": base link '" + base_link + "' not in the URDF");
  std::vector<MergedBody> bodies(1);
  addLink(model, base, 0, Eigen::Isometry3d::Identity(), robot, bodies);
  for (MergedBody& b : bodies)
    computeFrame(b, robot);
  return bodies;
}

Eigen::Isometry3d worldPose(const urdf::ModelInterface& model, const std::string& link)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  urdf::LinkConstSharedPtr current = model.getLink(link);
  while (current && current->parent_joint)
  {
    pose = toIsometry(current->parent_joint->parent_to_joint_origin_transform) * pose;
    current = model.getLink(current->parent_joint->parent_link_name);
  }
  return pose;
}
}  // namespace vrrw_physics
