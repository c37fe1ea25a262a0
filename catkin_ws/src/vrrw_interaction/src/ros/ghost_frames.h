#pragma once
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "ghost_interface.h"

namespace vrrw_interaction
{
/// \brief The ghosts where rviz's "Ghosts" RobotModel and ./vrrw render draw them: every link at the ghost state
/// as tf frame ghost/<link> (live values for the grippers and the arms without a ghost), 30 times a second
/// while anything moved, else once a second; and /ghost_description, the scene's URDF in each robot's ghost
/// tint (ghostDescription).
class GhostFrames
{
public:
  GhostFrames(WorldView& view, std::vector<GhostInterface*> ghosts);

private:
  /// \brief 30 Hz (ROS time): sends the frames when the ghost state changed or a second passed (mutex held).
  void tick();
  void send(const Eigen::VectorXd& ghost_state, const ros::Time& stamp);

  WorldView& view_;
  const std::vector<GhostInterface*> ghosts_;
  tf2_ros::TransformBroadcaster broadcaster_;
  Eigen::VectorXd sent_;  ///< PROTECTED BY the world's mutex: the ghost state last sent
  ros::Time sent_at_;     ///< PROTECTED BY the world's mutex
  ros::Timer timer_;
};
}  // namespace vrrw_interaction
