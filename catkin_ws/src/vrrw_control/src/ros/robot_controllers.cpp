#include <cmath>
#include <std_msgs/Bool.h>
#include <vrrw_control/ros/robot_controllers.h>
#include <vrrw_control/ros/ros_drive_link.h>

namespace vrrw_control
{
RobotControllers::RobotControllers(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name,
                                   const RobotDescription& robot, const std::string& mode,
                                   std::unique_ptr<RobotHardware> hardware, std::function<ros::Time()> clock)
  : nh_(nh), name_(name), mode_(mode), robot_(robot), hw_(std::move(hardware)), clock_(std::move(clock))
{
  makeArm(pnh);
  makeGripper(pnh);
  free_drive_ = nh_.subscribe<std_msgs::Bool>("free_drive_active", 1, [this](const std_msgs::BoolConstPtr& msg) {
    arm_server_->setFreeDrive(msg->data, clock_());
  });
}

RobotControllers::~RobotControllers() = default;

std::vector<std::string> RobotControllers::joints(const RobotDescription& robot)
{
  std::vector<std::string> joints = robot.arm_joints;
  if (!robot.gripper_joint.empty())
    joints.push_back(robot.gripper_joint);
  return joints;
}

void RobotControllers::makeArm(ros::NodeHandle& pnh)
{
  const auto limits = loadJointLimits(robot_.urdf, robot_.arm_joints, robot_.acceleration_limits);
  ValidationOptions gate;
  gate.start_tolerance = pnh.param("start_tolerance", gate.start_tolerance);
  ArmController::Options options;
  // real mode is strict (no splicing): a goal is previewed from rest and starts where the arm is, as the real
  // driver's start tolerance requires
  options.splice = mode_ != "real" && pnh.param("insert_blend", true);
  // stops decelerate at each joint's acceleration limit; the parameter (rad/s^2) only for a joint without one
  const double stop_deceleration = pnh.param("stop_deceleration", 3.0);
  for (const auto& l : limits)
    options.stop_deceleration.push_back(std::isfinite(l.max_acceleration) ? l.max_acceleration : stop_deceleration);
  arm_ = std::make_unique<ArmController>(*hw_, robot_.arm_joints, TrajectoryValidator(limits, gate), options);

  server_options_.clock = clock_;
  server_options_.clock_origin = clock_();
  server_options_.defaults = Tolerances::uniform(
      robot_.arm_joints.size(), pnh.param("path_tolerance", 0.0), pnh.param("goal_tolerance", 0.01),
      pnh.param("goal_velocity_tolerance", 0.0), pnh.param("goal_time", 1.0));
  server_options_.confirm_timeout = pnh.param("confirm_timeout", 120.0);  // s a person has to confirm a real goal
  server_options_.queue_size = pnh.param("action_queue_size", server_options_.queue_size);
  // physics mode cycles at the simulation's 1 ms step: feedback at 50 Hz, as for every observer (a running
  // workspace's CPU goes mostly to messages)
  const double feedback_rate = pnh.param("feedback_rate", mode_ == "physics" ? 50.0 : 0.0);
  server_options_.feedback_period = feedback_rate > 0.0 ? 1.0 / feedback_rate : 0.0;
  std::unique_ptr<RealDriverRelay> relay;
  if (mode_ == "real")
    relay = makeRealRelay(pnh);
  arm_server_ = std::make_unique<ArmActionServer>(nh_, *arm_, *hw_, server_options_, std::move(relay), real_.get());
  command_ = std::make_unique<ArmCommandTopic>(nh_, *arm_, *arm_server_, *hw_, server_options_, mode_ == "real");
}

std::unique_ptr<RealDriverRelay> RobotControllers::makeRealRelay(ros::NodeHandle& pnh)
{
  const std::string prefix = pnh.param("strip_prefix", true) ? name_ + "_" : "";
  const std::string real_states = pnh.param<std::string>("real_joint_states", "");
  if (!real_states.empty())
  {
    real_link_ = std::make_unique<RosDriveLink>(nh_, real_states, prefix);
    real_ = std::make_unique<RealRobot>(robot_.arm_joints, *real_link_);
  }
  return std::make_unique<RealDriverRelay>(
      pnh.param<std::string>("real_driver_action", "scaled_pos_joint_traj_controller/follow_joint_trajectory"), prefix);
}

void RobotControllers::makeGripper(ros::NodeHandle& pnh)
{
  if (robot_.gripper_joint.empty())
    return;
  GripperOptions g;
  const auto limits = loadJointLimits(robot_.urdf, { robot_.gripper_joint }).front();
  g.min_position = limits.min_position;
  g.max_position = limits.max_position;
  g.max_velocity = std::isfinite(limits.max_velocity) ? limits.max_velocity : g.max_velocity;
  g.min_duration = pnh.param("gripper_min_duration", g.min_duration);
  g.lever_arm = robot_.gripper_lever_arm;
  g.max_grip_force = robot_.max_grip_force;
  gripper_ = std::make_unique<GripperController>(*hw_, robot_.gripper_joint, g);
  gripper_server_ = std::make_unique<GripperActionServer>(nh_, *gripper_, *hw_, server_options_,
                                                          pnh.param("allow_stalling", true));
}

// ros_control's order: read the hardware (and the real arm, measured), update the controllers, write commands.
void RobotControllers::cycle(const ros::Time& now, double period)
{
  const double t = (now - server_options_.clock_origin).toSec();
  hw_->read(t, period);
  if (real_)
    real_->read(t, period);
  arm_server_->update(now);
  if (gripper_server_)
    gripper_server_->update(now);
  hw_->write(t, period);
}

bool RobotControllers::idle() const
{
  return !arm_server_->active() && !(gripper_server_ && gripper_server_->active());
}

void RobotControllers::interrupt(const std::string& why)
{
  arm_server_->suspend(why);
  if (gripper_server_)
    gripper_server_->suspend(why);
}
}  // namespace vrrw_control
