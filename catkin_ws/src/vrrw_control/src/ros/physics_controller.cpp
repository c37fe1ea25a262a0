// PhysicsController: a robot's controllers inside physics_node, loaded by pluginlib
// (vrrw_control/PhysicsController, base vrrw_physics::RobotController), the same RobotControllers that
// controller_node runs in fake and real mode, on a PhysicsRobot that physics measures and commands each step.
#include <pluginlib/class_list_macros.hpp>
#include <vrrw_control/physics_robot.h>
#include <vrrw_control/ros/robot_controllers.h>
#include <vrrw_physics/ros/robot_controller.h>

namespace vrrw_control
{
class PhysicsController : public vrrw_physics::RobotController
{
public:
  void initialize(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, const std::string& robot,
                  std::function<ros::Time()> clock) override
  {
    ros::NodeHandle pnh(nh, "controller");  // /<robot>/controller/*: controller_node's private parameters
    pnh.setParam("mode", "physics");         // as controller_node's ~mode: tools read which mode runs
    const RobotDescription description = describeRobot(scene, robot, pnh);
    joints_ = RobotControllers::joints(description);
    auto hardware = std::make_unique<PhysicsRobot>(joints_);
    robot_ = hardware.get();
    controllers_ = std::make_unique<RobotControllers>(nh, pnh, robot, description, "physics", std::move(hardware),
                                                      std::move(clock));
    ROS_INFO_STREAM(nh.getNamespace() << ": controller up in physics_node (lockstep), arm "
                                      << description.arm_joints.size() << " joints, gripper '"
                                      << description.gripper_joint << "'");
  }

  std::vector<std::string> joints() const override { return joints_; }

  void update(const ros::Time& time, const ros::Duration& period, const vrrw_physics::MeasuredJoints& measured,
              vrrw_physics::DriveTargets& targets) override
  {
    robot_->measure(measured.position, measured.velocity, measured.effort);
    controllers_->cycle(time, period.toSec());
    targets.position = robot_->command().positions;
    targets.velocity = robot_->command().velocities;
    targets.force_limit = robot_->effortLimits();
  }

  bool idle() const override { return controllers_->idle(); }

  void interrupt(const std::string& why) override
  {
    controllers_->interrupt(why);
    robot_->holdMeasured();
  }

private:
  std::vector<std::string> joints_;
  PhysicsRobot* robot_ = nullptr;  ///< owned by controllers_
  std::unique_ptr<RobotControllers> controllers_;
};
}  // namespace vrrw_control

PLUGINLIB_EXPORT_CLASS(vrrw_control::PhysicsController, vrrw_physics::RobotController)
