#pragma once
#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>
#include <vrrw_scene/scene.h>

namespace vrrw_kinematics
{
/// \brief One URDF joint: origin (parent link to joint frame at zero), axis, limits, mimic.
struct JointModel
{
  enum class Type { Fixed, Revolute, Continuous, Prismatic };
  std::string name;
  Type type = Type::Fixed;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double lower = 0.0;
  double upper = 0.0;
  double max_velocity = 0.0;
  int parent_link = -1;
  int child_link = -1;
  int variable = -1;  ///< index in the variable vector; -1 for fixed and mimic joints
  int mimic_variable = -1;
  double mimic_multiplier = 1.0;
  double mimic_offset = 0.0;

  bool moves() const { return type != Type::Fixed; }
  /// \brief Transform from the parent link frame to the child link frame at joint value q.
  Eigen::Isometry3d transform(double q) const;
};

/// \brief One URDF link with its collision geometry in the link frame.
struct LinkModel
{
  std::string name;
  int parent_joint = -1;
  int parent_link = -1;
  std::vector<int> child_links;
  std::vector<vrrw_scene::Shape> collision;
};

/// \brief A whole URDF as a kinematic tree (urdfdom), links in topological order.
///
/// Variables are the non-fixed, non-mimic joints in link order; mimic joints follow theirs.
class RobotModel
{
public:
  /// \brief Parses a URDF XML string; throws KinematicsError(InvalidUrdf) naming the reason.
  static RobotModel fromUrdf(const std::string& urdf_xml);

  const std::string& name() const { return name_; }
  const std::vector<LinkModel>& links() const { return links_; }
  const std::vector<JointModel>& joints() const { return joints_; }
  const std::vector<int>& variableJoints() const { return variable_joints_; }
  std::size_t variableCount() const { return variable_joints_.size(); }

  /// \brief Link index by name; throws KinematicsError(UnknownLink).
  int linkIndex(const std::string& link) const;
  /// \brief Joint index by name; throws KinematicsError(InvalidArgument).
  int jointIndex(const std::string& joint) const;
  /// \brief Variable index of a movable, non-mimic joint; -1 when unknown or not a variable.
  int variableIndex(const std::string& joint) const;
  const std::vector<std::string>& variableNames() const { return variable_names_; }

  /// \brief Zero within limits for every variable (clamped into [lower, upper]).
  Eigen::VectorXd neutralState() const;
  /// \brief Value of joint j given the variable vector (handles mimic joints).
  double jointValue(const JointModel& joint, const Eigen::VectorXd& variables) const;
  /// \brief World (root) pose of every link, indexed like links().
  void linkTransforms(const Eigen::VectorXd& variables, std::vector<Eigen::Isometry3d>& out) const;
  /// \brief Pose of `link` in the frame of `reference`.
  Eigen::Isometry3d relativeTransform(const Eigen::VectorXd& variables, const std::string& reference,
                                      const std::string& link) const;
  /// \brief True when `descendant` lies in the subtree below `ancestor` (or is it).
  bool isDescendant(int descendant, int ancestor) const;

private:
  std::string name_;
  std::vector<LinkModel> links_;
  std::vector<JointModel> joints_;
  std::vector<int> variable_joints_;
  std::vector<std::string> variable_names_;
  std::map<std::string, int> link_index_;
  std::map<std::string, int> joint_index_;
};
}  // namespace vrrw_kinematics
