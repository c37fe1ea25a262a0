#include "ghost_frames.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_interaction/ghost_description.h>

namespace vrrw_interaction
{
GhostFrames::GhostFrames(WorldView& view, std::vector<GhostInterface*> ghosts) : view_(view), ghosts_(std::move(ghosts))
{
  ros::NodeHandle nh;
  nh.setParam("/ghost_description", ghostDescription(view_.scene()));
  timer_ = nh.createTimer(ros::Duration(1.0 / 30.0), [this](const ros::TimerEvent&) { tick(); });
}

void GhostFrames::tick()
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  Eigen::VectorXd state = view_.liveState();
  for (GhostInterface* ghost : ghosts_)
    ghost->ghostInto(state);
  const ros::Time now = ros::Time::now();
  // tf refuses a frame twice at one stamp (TF_REPEATED_DATA): under sim time, timer events that queued up
  // fire at one clock reading; the next tick sends the ghost as it is then.
  if (now <= sent_at_)
    return;
  if (sent_.size() == state.size() && (sent_ - state).cwiseAbs().maxCoeff() < 1e-9 && now - sent_at_ < ros::Duration(1.0))
    return;
  send(state, now);
  sent_ = state;
  sent_at_ = now;
}

void GhostFrames::send(const Eigen::VectorXd& ghost_state, const ros::Time& stamp)
{
  const vrrw_kinematics::RobotModel& model = view_.world().model();
  std::vector<Eigen::Isometry3d> links;
  model.linkTransforms(ghost_state, links);
  std::vector<geometry_msgs::TransformStamped> frames;
  frames.reserve(links.size());
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    geometry_msgs::TransformStamped frame = tf2::eigenToTransform(links[l]);
    frame.header.stamp = stamp;
    frame.header.frame_id = model.links()[0].name;
    frame.child_frame_id = "ghost/" + model.links()[l].name;
    frames.push_back(frame);
  }
  broadcaster_.sendTransform(frames);
}
}  // namespace vrrw_interaction
