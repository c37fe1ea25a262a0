#include <vrrw_demos/tcp_kinematics.h>

#include <vrrw_common/joint_mapping.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_kinematics/kinematic_chain.h>
#include <vrrw_kinematics/kinematics_error.h>
#include <vrrw_kinematics/robot_model.h>

namespace vrrw_demos
{
TcpKinematics::TcpKinematics(const Demonstration& demo, const RobotTrack& track)
{
  const std::string where = demo.source + ": /demos/metadata: ";
  const auto robot = demo.metadata.robots.find(track.robot);
  if (demo.metadata.robot_description.empty())
    throw DemoError(where + "no robot_description (a bag from ./vrrw record or /demos/start has one)");
  if (robot == demo.metadata.robots.end() || robot->second.tcp_link.empty())
    throw DemoError(where + "no tcp_link for robot '" + track.robot + "'");
  try
  {
    const auto model = vrrw_kinematics::RobotModel::fromUrdf(demo.metadata.robot_description);
    chain_ = std::make_unique<vrrw_kinematics::KinematicChain>(model, model.links().front().name,
                                                               robot->second.tcp_link);
  }
  catch (const vrrw_kinematics::KinematicsError& e)
  {
    throw DemoError(where + "robot_description: " + e.what());
  }
  const auto chain_in_track = vrrw_common::findJoints(track.joint_names, chain_->jointNames());
  if (!chain_in_track)
    throw DemoError(where + "the chain to " + robot->second.tcp_link + " moves joints the recorded states of '" +
                    track.robot + "' do not all have");
  index_ = *chain_in_track;
}

TcpKinematics::~TcpKinematics() = default;
TcpKinematics::TcpKinematics(TcpKinematics&&) noexcept = default;

Eigen::Isometry3d TcpKinematics::at(const RobotState& state) const
{
  return at(state.positions);
}

Eigen::Isometry3d TcpKinematics::at(const std::vector<double>& positions) const
{
  Eigen::VectorXd q(static_cast<Eigen::Index>(index_.size()));
  for (std::size_t j = 0; j < index_.size(); ++j)
    q[static_cast<Eigen::Index>(j)] = positions[index_[j]];
  return chain_->fk(q);
}

Eigen::Isometry3d toIsometry(const Pose& pose)
{
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.position[0], pose.position[1], pose.position[2]);
  out.linear() = Eigen::Quaterniond(pose.orientation[3], pose.orientation[0], pose.orientation[1],
                                    pose.orientation[2]).normalized().toRotationMatrix();
  return out;
}
}  // namespace vrrw_demos
