#pragma once
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "ghost_interface.h"
#include "send_schedule.h"

namespace vrrw_interaction
{
/// \brief The ghosts where rviz's "Ghosts" RobotModel and ./vrrw render draw them: every link at the ghost state
/// as tf frame ghost/<link> (live values for the grippers and the arms without a ghost), sent at the live states'
/// instants (WorldView::onInstant) when the ghost state changed or a second passed (SendSchedule), and at once
/// after a ghost request; and /ghost_description, the scene's URDF in each robot's ghost tint (ghostDescription).
class GhostFrames
{
public:
  GhostFrames(WorldView& view, std::vector<GhostInterface*> ghosts);

private:
  /// \brief Sends the frames at `stamp` when they changed or (at a state's instant, not `requested`) the
  /// keepalive is due (mutex held).
  void update(const ros::Time& stamp, bool requested);
  void send(const Eigen::VectorXd& ghost_state, const ros::Time& stamp);

  WorldView& view_;
  const std::vector<GhostInterface*> ghosts_;
  tf2_ros::TransformBroadcaster broadcaster_;
  Eigen::VectorXd sent_;    ///< PROTECTED BY the world's mutex: the ghost state last sent
  SendSchedule schedule_;  ///< PROTECTED BY the world's mutex
};
}  // namespace vrrw_interaction
