#include "ghost_frames.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_interaction/ghost_description.h>

namespace vrrw_interaction
{
namespace
{
/// rad or m: a joint that moved less since the last send is not sent again before the keepalive (0.1 mm at 1 m,
/// under a pixel in rviz). A released Robotiq's fingers creep 3e-6 rad over seconds in physics, 4e-8 rad a state:
/// they sent the frames at every state.
constexpr double kUnseen = 1e-4;
}  // namespace

GhostFrames::GhostFrames(WorldView& view, std::vector<GhostInterface*> ghosts) : view_(view), ghosts_(std::move(ghosts))
{
  ros::NodeHandle nh;
  nh.setParam("/ghost_description", ghostDescription(view_.scene()));
  view_.onInstant([this](const ros::Time& stamp) { update(stamp, false); });
  for (GhostInterface* ghost : ghosts_)
    ghost->on_published = [this](const ros::Time& stamp) { update(stamp, true); };
}

void GhostFrames::update(const ros::Time& stamp, bool requested)
{
  Eigen::VectorXd state = view_.liveState();
  for (GhostInterface* ghost : ghosts_)
    ghost->ghostInto(state, stamp);
  const bool changed = sent_.size() != state.size() || (sent_ - state).cwiseAbs().maxCoeff() >= kUnseen;
  // a request sends its change at once; tf refuses a frame twice at one stamp (TF_REPEATED_DATA), so a request at
  // the instant the frames were last sent at leaves its change to the next state's instant
  if (!(requested ? changed && (stamp > schedule_.last() || schedule_.due(stamp, true)) : schedule_.due(stamp, changed)))
    return;
  send(state, stamp);
  sent_ = state;
  schedule_.sent(stamp);
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
