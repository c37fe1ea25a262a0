#include <vrrw_physics/joint_frames.h>

#include <stdexcept>

#include <vrrw_scene/urdf_geometry.h>

namespace vrrw_physics
{
namespace
{
bool movable(const urdf::Joint& joint)
{
  return joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS ||
         joint.type == urdf::Joint::PRISMATIC;
}

int indexOf(const std::vector<std::string>& names, const std::string& name)
{
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name)
      return int(i);
  return -1;
}
}  // namespace

JointFrames::JointFrames(const urdf::ModelInterface& model, const std::vector<std::string>& joints)
  : size_(joints.size())
{
  for (const std::string& name : joints)
  {
    const urdf::JointConstSharedPtr joint = model.getJoint(name);
    if (!joint || !movable(*joint))
      throw std::invalid_argument("joint frames: " + name + ": no revolute, continuous or prismatic joint of the URDF");
  }
  for (const auto& [name, joint] : model.joints_)
  {
    if (!movable(*joint))
      continue;
    Joint j;
    j.source = indexOf(joints, name);
    if (j.source < 0 && joint->mimic)  // a mimic joint physics does not report follows its master
    {
      j.source = indexOf(joints, joint->mimic->joint_name);
      j.multiplier = joint->mimic->multiplier;
      j.offset = joint->mimic->offset;
    }
    if (j.source < 0)
      continue;  // another robot's
    j.origin = vrrw_scene::toIsometry(joint->parent_to_joint_origin_transform);
    j.axis = Eigen::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z).normalized();
    j.prismatic = joint->type == urdf::Joint::PRISMATIC;
    joints_.push_back(j);
    frames_.push_back({ joint->parent_link_name, joint->child_link_name, Eigen::Isometry3d::Identity() });
  }
}

const std::vector<JointFrames::Frame>& JointFrames::at(const std::vector<double>& positions)
{
  if (positions.size() != size_)
    throw std::invalid_argument("joint frames: " + std::to_string(positions.size()) + " positions for " +
                                std::to_string(size_) + " joints");
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    const Joint& j = joints_[i];
    const double q = j.multiplier * positions[std::size_t(j.source)] + j.offset;
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (j.prismatic)
      motion.translation() = q * j.axis;
    else
      motion.linear() = Eigen::AngleAxisd(q, j.axis).toRotationMatrix();
    frames_[i].pose = j.origin * motion;
  }
  return frames_;
}
}  // namespace vrrw_physics
