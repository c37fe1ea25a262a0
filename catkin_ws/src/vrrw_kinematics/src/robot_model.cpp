#include "vrrw_kinematics/robot_model.h"

#include <urdf_parser/urdf_parser.h>

#include <cstdlib>
#include <deque>
#include <fstream>
#include <sstream>

#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_scene/mesh_path.h"

namespace vrrw_kinematics
{
namespace
{
Eigen::Isometry3d toEigen(const urdf::Pose& pose)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

bool toShape(const urdf::Collision& collision, vrrw_scene::Shape& shape)
{
  if (!collision.geometry)
    return false;
  shape.origin = toEigen(collision.origin);
  switch (collision.geometry->type)
  {
    case urdf::Geometry::BOX:
    {
      const auto& box = static_cast<const urdf::Box&>(*collision.geometry);
      shape.type = vrrw_scene::Shape::Type::Box;
      shape.box_size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      return true;
    }
    case urdf::Geometry::CYLINDER:
    {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(*collision.geometry);
      shape.type = vrrw_scene::Shape::Type::Cylinder;
      shape.radius = cylinder.radius;
      shape.length = cylinder.length;
      return true;
    }
    case urdf::Geometry::SPHERE:
    {
      shape.type = vrrw_scene::Shape::Type::Sphere;
      shape.radius = static_cast<const urdf::Sphere&>(*collision.geometry).radius;
      return true;
    }
    case urdf::Geometry::MESH:
    {
      const auto& mesh = static_cast<const urdf::Mesh&>(*collision.geometry);
      shape.type = vrrw_scene::Shape::Type::Mesh;
      shape.mesh_path = vrrw_scene::resolveMeshPath(mesh.filename);
      shape.mesh_scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
      return !shape.mesh_path.empty();
    }
  }
  return false;
}

JointModel::Type toType(int urdf_type)
{
  switch (urdf_type)
  {
    case urdf::Joint::REVOLUTE: return JointModel::Type::Revolute;
    case urdf::Joint::CONTINUOUS: return JointModel::Type::Continuous;
    case urdf::Joint::PRISMATIC: return JointModel::Type::Prismatic;
    default: return JointModel::Type::Fixed;
  }
}
}  // namespace

Eigen::Isometry3d JointModel::transform(double q) const
{
  switch (type)
  {
    case Type::Revolute:
    case Type::Continuous:
    {
      Eigen::Isometry3d t = origin;
      t.linear() = origin.linear() * Eigen::AngleAxisd(q, axis).toRotationMatrix();
      return t;
    }
    case Type::Prismatic:
    {
      Eigen::Isometry3d t = origin;
      t.translation() += origin.linear() * (axis * q);
      return t;
    }
    case Type::Fixed: break;
  }
  return origin;
}

RobotModel RobotModel::fromUrdf(const std::string& urdf_xml)
{
  const urdf::ModelInterfaceSharedPtr urdf_model = urdf::parseURDF(urdf_xml);
  if (!urdf_model || !urdf_model->getRoot())
    throw KinematicsError(ErrorCode::InvalidUrdf, "urdf: not a valid URDF document (urdfdom could not parse it)");

  RobotModel model;
  model.name_ = urdf_model->getName();
  std::deque<urdf::LinkConstSharedPtr> queue{ urdf_model->getRoot() };
  while (!queue.empty())
  {
    const urdf::LinkConstSharedPtr link = queue.front();
    queue.pop_front();
    LinkModel link_model;
    link_model.name = link->name;
    for (const auto& collision : link->collision_array)
    {
      vrrw_scene::Shape shape;
      if (collision && toShape(*collision, shape))
        link_model.collision.push_back(shape);
    }
    const int link_index = static_cast<int>(model.links_.size());
    if (link->parent_joint)
    {
      const urdf::Joint& joint = *link->parent_joint;
      JointModel joint_model;
      joint_model.name = joint.name;
      joint_model.type = toType(joint.type);
      joint_model.origin = toEigen(joint.parent_to_joint_origin_transform);
      joint_model.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
      if (joint_model.moves())
      {
        if (joint_model.axis.norm() < 1e-12)
          throw KinematicsError(ErrorCode::InvalidUrdf, "urdf: joint " + joint.name + ": zero axis");
        joint_model.axis.normalize();
      }
      if (joint.limits)
      {
        joint_model.lower = joint.limits->lower;
        joint_model.upper = joint.limits->upper;
        joint_model.max_velocity = joint.limits->velocity;
      }
      if (joint_model.type == JointModel::Type::Continuous)
      {
        joint_model.lower = -M_PI;
        joint_model.upper = M_PI;
      }
      if (joint_model.moves() && joint_model.lower > joint_model.upper)
        throw KinematicsError(ErrorCode::InvalidUrdf,
                              "urdf: joint " + joint.name + ": lower limit above upper limit");
      joint_model.parent_link = model.link_index_.at(joint.parent_link_name);
      joint_model.child_link = link_index;
      if (joint.mimic)
      {
        joint_model.mimic_multiplier = joint.mimic->multiplier;
        joint_model.mimic_offset = joint.mimic->offset;
      }
      link_model.parent_joint = static_cast<int>(model.joints_.size());
      link_model.parent_link = joint_model.parent_link;
      model.links_[joint_model.parent_link].child_links.push_back(link_index);
      model.joint_index_[joint.name] = link_model.parent_joint;
      model.joints_.push_back(joint_model);
    }
    model.link_index_[link->name] = link_index;
    model.links_.push_back(link_model);
    for (const auto& child : link->child_links)
      queue.push_back(child);
  }

  for (std::size_t j = 0; j < model.joints_.size(); ++j)
  {
    JointModel& joint = model.joints_[j];
    const urdf::JointConstSharedPtr urdf_joint = urdf_model->getJoint(joint.name);
    if (!joint.moves() || urdf_joint->mimic)
      continue;
    joint.variable = static_cast<int>(model.variable_joints_.size());
    model.variable_joints_.push_back(static_cast<int>(j));
    model.variable_names_.push_back(joint.name);
  }
  for (JointModel& joint : model.joints_)
  {
    const urdf::JointConstSharedPtr urdf_joint = urdf_model->getJoint(joint.name);
    if (!joint.moves() || !urdf_joint->mimic)
      continue;
    const auto it = model.joint_index_.find(urdf_joint->mimic->joint_name);
    if (it == model.joint_index_.end() || model.joints_[it->second].variable < 0)
      throw KinematicsError(ErrorCode::InvalidUrdf, "urdf: joint " + joint.name + ": mimics unknown joint " +
                                                        urdf_joint->mimic->joint_name);
    joint.mimic_variable = model.joints_[it->second].variable;
  }
  return model;
}

int RobotModel::linkIndex(const std::string& link) const
{
  const auto it = link_index_.find(link);
  if (it == link_index_.end())
    throw KinematicsError(ErrorCode::UnknownLink, "link " + link + ": not in the URDF");
  return it->second;
}

int RobotModel::jointIndex(const std::string& joint) const
{
  const auto it = joint_index_.find(joint);
  if (it == joint_index_.end())
    throw KinematicsError(ErrorCode::InvalidArgument, "joint " + joint + ": not in the URDF");
  return it->second;
}

int RobotModel::variableIndex(const std::string& joint) const
{
  const auto it = joint_index_.find(joint);
  return it == joint_index_.end() ? -1 : joints_[it->second].variable;
}

Eigen::VectorXd RobotModel::neutralState() const
{
  Eigen::VectorXd q(variable_joints_.size());
  for (std::size_t i = 0; i < variable_joints_.size(); ++i)
  {
    const JointModel& joint = joints_[variable_joints_[i]];
    q[i] = std::min(std::max(0.0, joint.lower), joint.upper);
  }
  return q;
}

double RobotModel::jointValue(const JointModel& joint, const Eigen::VectorXd& variables) const
{
  if (joint.variable >= 0)
    return variables[joint.variable];
  if (joint.mimic_variable >= 0)
    return joint.mimic_multiplier * variables[joint.mimic_variable] + joint.mimic_offset;
  return 0.0;
}

void RobotModel::linkTransforms(const Eigen::VectorXd& variables, std::vector<Eigen::Isometry3d>& out) const
{
  out.resize(links_.size());
  out[0] = Eigen::Isometry3d::Identity();
  for (std::size_t l = 1; l < links_.size(); ++l)
  {
    const JointModel& joint = joints_[links_[l].parent_joint];
    out[l] = out[joint.parent_link] * joint.transform(jointValue(joint, variables));
  }
}

Eigen::Isometry3d RobotModel::relativeTransform(const Eigen::VectorXd& variables, const std::string& reference,
                                                const std::string& link) const
{
  const int reference_index = linkIndex(reference);
  const int link_index = linkIndex(link);
  std::vector<Eigen::Isometry3d> poses;
  linkTransforms(variables, poses);
  return poses[reference_index].inverse() * poses[link_index];
}

bool RobotModel::isDescendant(int descendant, int ancestor) const
{
  for (int l = descendant; l >= 0; l = links_[l].parent_link)
    if (l == ancestor)
      return true;
  return false;
}
}  // namespace vrrw_kinematics
