#include "vrrw_kinematics/kinematic_chain.h"

#include <algorithm>
#include <cmath>

#include "vrrw_kinematics/kinematics_error.h"

namespace vrrw_kinematics
{
namespace
{
Eigen::Isometry3d applyJoint(const Eigen::Isometry3d& frame, const ChainJoint& joint, double q)
{
  Eigen::Isometry3d out = frame * joint.before;
  if (joint.prismatic)
    out.translation() += out.linear() * (joint.axis * q);
  else
    out.linear() = out.linear() * Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
  return out;
}
}  // namespace

KinematicChain::KinematicChain(const RobotModel& model, const std::string& base, const std::string& tip)
  : base_(base), tip_(tip)
{
  const int base_index = model.linkIndex(base);
  const int tip_index = model.linkIndex(tip);
  std::vector<int> path;
  for (int l = tip_index; l != base_index; l = model.links()[l].parent_link)
  {
    if (l < 0 || model.links()[l].parent_link < 0)
      throw KinematicsError(ErrorCode::NotSerialChain,
                            "chain " + base + " -> " + tip + ": " + tip + " is not below " + base +
                                " in the URDF tree, so they do not form a serial chain");
    path.push_back(l);
  }
  std::reverse(path.begin(), path.end());

  link_names_.push_back(base);
  links_.push_back(ChainLink{});
  Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();
  for (const int l : path)
  {
    const JointModel& joint = model.joints()[model.links()[l].parent_joint];
    if (joint.moves() && joint.variable < 0)
      throw KinematicsError(ErrorCode::NotSerialChain,
                            "chain " + base + " -> " + tip + ": joint " + joint.name + " is a mimic joint");
    if (joint.moves())
    {
      ChainJoint chain_joint;
      chain_joint.name = joint.name;
      chain_joint.prismatic = joint.type == JointModel::Type::Prismatic;
      chain_joint.continuous = joint.type == JointModel::Type::Continuous;
      chain_joint.before = pending * joint.origin;
      chain_joint.axis = joint.axis;
      chain_joint.lower = joint.lower;
      chain_joint.upper = joint.upper;
      chain_joint.max_velocity = joint.max_velocity;
      joints_.push_back(chain_joint);
      pending = Eigen::Isometry3d::Identity();
    }
    else
    {
      pending = pending * joint.origin;
    }
    link_names_.push_back(model.links()[l].name);
    links_.push_back(ChainLink{ static_cast<int>(joints_.size()) - 1, pending });
  }
  after_ = pending;
  if (joints_.empty())
    throw KinematicsError(ErrorCode::NotSerialChain,
                          "chain " + base + " -> " + tip + ": no movable joint between the links");
}

KinematicChain KinematicChain::fromUrdf(const std::string& urdf_xml, const std::string& base, const std::string& tip)
{
  return KinematicChain(RobotModel::fromUrdf(urdf_xml), base, tip);
}

std::vector<std::string> KinematicChain::jointNames() const
{
  std::vector<std::string> names;
  for (const ChainJoint& joint : joints_)
    names.push_back(joint.name);
  return names;
}

Eigen::VectorXd KinematicChain::lowerLimits() const
{
  Eigen::VectorXd v(joints_.size());
  for (std::size_t i = 0; i < joints_.size(); ++i)
    v[i] = joints_[i].lower;
  return v;
}

Eigen::VectorXd KinematicChain::upperLimits() const
{
  Eigen::VectorXd v(joints_.size());
  for (std::size_t i = 0; i < joints_.size(); ++i)
    v[i] = joints_[i].upper;
  return v;
}

Eigen::VectorXd KinematicChain::midLimits() const
{
  return 0.5 * (lowerLimits() + upperLimits());
}

bool KinematicChain::withinLimits(const Eigen::VectorXd& q, double tolerance) const
{
  return jointOutsideLimits(q, tolerance).empty();
}

std::string KinematicChain::jointOutsideLimits(const Eigen::VectorXd& q, double tolerance) const
{
  if (static_cast<std::size_t>(q.size()) != joints_.size())
    return "(joint count " + std::to_string(q.size()) + " != " + std::to_string(joints_.size()) + ")";
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (!std::isfinite(q[i]) ||
        (!joints_[i].continuous && (q[i] < joints_[i].lower - tolerance || q[i] > joints_[i].upper + tolerance)))
      return joints_[i].name;
  return "";
}

Eigen::VectorXd KinematicChain::randomState(std::mt19937_64& rng) const
{
  Eigen::VectorXd q(joints_.size());
  for (std::size_t i = 0; i < joints_.size(); ++i)
    q[i] = std::uniform_real_distribution<double>(joints_[i].lower, joints_[i].upper)(rng);
  return q;
}

Eigen::Isometry3d KinematicChain::fk(const Eigen::VectorXd& q) const
{
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < joints_.size(); ++i)
    frame = applyJoint(frame, joints_[i], q[i]);
  return frame * after_;
}

Eigen::Isometry3d KinematicChain::fk(const Eigen::VectorXd& q, const std::string& link) const
{
  const auto it = std::find(link_names_.begin(), link_names_.end(), link);
  if (it == link_names_.end())
    throw KinematicsError(ErrorCode::UnknownLink, "link " + link + ": not in the chain " + base_ + " -> " + tip_);
  const ChainLink& chain_link = links_[it - link_names_.begin()];
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  for (int i = 0; i <= chain_link.joint; ++i)
    frame = applyJoint(frame, joints_[i], q[i]);
  return frame * chain_link.offset;
}

void KinematicChain::jacobian(const Eigen::VectorXd& q, Eigen::Isometry3d& tip,
                              Eigen::Matrix<double, 6, Eigen::Dynamic>& jac) const
{
  const std::size_t n = joints_.size();
  jac.resize(6, static_cast<Eigen::Index>(n));
  Eigen::Matrix3Xd axes(3, n), origins(3, n);
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < n; ++i)
  {
    frame = applyJoint(frame, joints_[i], q[i]);
    axes.col(i) = frame.linear() * joints_[i].axis;
    origins.col(i) = frame.translation();
  }
  tip = frame * after_;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (joints_[i].prismatic)
    {
      jac.col(i).head<3>() = axes.col(i);
      jac.col(i).tail<3>().setZero();
    }
    else
    {
      jac.col(i).head<3>() = axes.col(i).cross(tip.translation() - origins.col(i));
      jac.col(i).tail<3>() = axes.col(i);
    }
  }
}

Eigen::Vector3d rotationError(const Eigen::Matrix3d& target, const Eigen::Matrix3d& current)
{
  const Eigen::AngleAxisd error(target * current.transpose());
  return error.axis() * error.angle();
}
}  // namespace vrrw_kinematics
