#pragma once
// The tf frames a robot's movable joints move, from the joint positions physics simulates.
#include <urdf_model/model.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace vrrw_physics
{
/// \brief Each revolute, continuous or prismatic joint of a URDF among `joints` as a frame: its child link in
/// its parent link at the joint's position (origin, then the motion along the axis), what robot_state_publisher
/// sends for a joint_states message. Fixed joints are left to /tf_static; a mimic joint physics does not report
/// follows its master (multiplier, offset).
class JointFrames
{
public:
  /// \brief `joints`: the order of the positions at(): a robot's joint states as physics reports them. A name
  /// that is no movable joint of `model` throws std::invalid_argument naming it.
  JointFrames(const urdf::ModelInterface& model, const std::vector<std::string>& joints);

  struct Frame
  {
    std::string parent, child;
    Eigen::Isometry3d pose;  ///< child in parent
  };

  /// \brief The frames at `positions` (in the order of the constructor's `joints`, that many).
  const std::vector<Frame>& at(const std::vector<double>& positions);

private:
  struct Joint
  {
    Eigen::Isometry3d origin;
    Eigen::Vector3d axis;
    bool prismatic = false;
    int source = -1;  ///< index into the positions
    double multiplier = 1.0, offset = 0.0;
  };
  std::size_t size_;  ///< positions at() takes
  std::vector<Joint> joints_;
  std::vector<Frame> frames_;  ///< the last at()'s, one per entry of joints_
};
}  // namespace vrrw_physics
