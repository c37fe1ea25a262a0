#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <vrrw_demos/demonstration.h>

namespace vrrw_kinematics
{
class KinematicChain;
}  // namespace vrrw_kinematics

namespace vrrw_demos
{
/// \brief The TCP of a recorded robot by forward kinematics of the bag's own URDF (its metadata's
/// robot_description and the robot's tcp_link): where the tool was at any recorded state, in the world.
class TcpKinematics
{
public:
  /// \brief Throws DemoError "SOURCE: /demos/metadata: reason" when the metadata has no URDF or TCP link for
  /// the robot, the URDF does not parse, or its chain to the TCP moves joints the track does not have.
  TcpKinematics(const Demonstration& demo, const RobotTrack& track);
  ~TcpKinematics();
  TcpKinematics(TcpKinematics&&) noexcept;

  /// \brief The TCP in the world at \a state.
  Eigen::Isometry3d at(const RobotState& state) const;
  /// \brief The TCP in the world at joint values \a positions (the track's arm joints, in its order).
  Eigen::Isometry3d at(const std::vector<double>& positions) const;

private:
  std::unique_ptr<vrrw_kinematics::KinematicChain> chain_;
  std::vector<std::size_t> index_;  ///< per chain joint: its column in the track
};

/// \brief \a pose as Eigen's rigid transform.
Eigen::Isometry3d toIsometry(const Pose& pose);
}  // namespace vrrw_demos
