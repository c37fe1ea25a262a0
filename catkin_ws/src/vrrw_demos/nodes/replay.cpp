#include "replay.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <mutex>

#include <actionlib/client/simple_action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/replay_path.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_kinematics/kinematic_chain.h>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_scene/robot_config.h>
#include <vrrw_trajectory/msg_conversions.h>

#include <vrrw_demos/ros/demo_bag.h>
#include "segment_report.h"

namespace vrrw_demos
{
namespace
{
using vrrw_common::Options;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = actionlib::SimpleActionClient<control_msgs::GripperCommandAction>;

/// The range a gripper goal may name: the actuated joint's URDF limits (none: unbounded).
struct GripperRange
{
  double lower = -1e9, upper = 1e9;
};

/// The robot's limits from the running workspace: URDF velocities, the config's accelerations, the gripper range.
void limits(ros::NodeHandle& nh, const RobotTrack& track, ReplayOptions& options, GripperRange& gripper)
{
  const std::string key = "/scene/robots/" + track.robot + "/";
  std::vector<std::string> joints;
  if (!nh.getParam(key + "arm_joints", joints))
    throw DemoError("replay: the running workspace has no robot '" + track.robot + "' (" + key + "arm_joints)");
  if (joints != track.joint_names)
  {
    std::string recorded, running;
    for (const auto& j : track.joint_names) recorded += " " + j;
    for (const auto& j : joints) running += " " + j;
    throw DemoError("replay: robot '" + track.robot + "' of the running scene has joints [" + running +
                    " ], the recording has [" + recorded + " ]: not the recorded robot");
  }
  std::string urdf;
  nh.getParam("/robot_description", urdf);
  const auto model = vrrw_kinematics::RobotModel::fromUrdf(urdf);
  const auto acceleration = vrrw_scene::loadAccelerationLimits(nh.param<std::string>(key + "config_file", ""),
                                                               track.robot + "_");
  for (const std::string& joint : joints)
  {
    const auto& urdf_joint = model.joints()[static_cast<std::size_t>(model.jointIndex(joint))];
    options.max_velocity.push_back(urdf_joint.max_velocity);
    const auto found = acceleration.find(joint);
    options.max_acceleration.push_back(found == acceleration.end() ? 1e9 : found->second);
  }
  const int finger = track.gripper_joint.empty() ? -1 : model.jointIndex(track.gripper_joint);
  if (finger >= 0)
  {
    const auto& joint = model.joints()[static_cast<std::size_t>(finger)];
    if (joint.type == vrrw_kinematics::JointModel::Type::Revolute || joint.type == vrrw_kinematics::JointModel::Type::Prismatic)
      gripper = { joint.lower, joint.upper };
  }
}

/// Real mode: the controller runs each goal in simulation, then holds it until confirmed (the operator said yes
/// already): asked again while it answers "still running in simulation", up to `seconds`.
void confirmIfReal(const std::string& ns, bool real, double seconds)
{
  if (!real)
    return;
  const std::string service = ns + "arm_controller/confirm_real_execution";
  std_srvs::Trigger confirm;
  static vrrw_common::PersistentServices services;
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
       ros::WallDuration(0.05).sleep())
    if (services.tryCall(service, confirm) && confirm.response.success)
      return;
  std::cerr << "replay: " << service << ": not confirmed (" << confirm.response.message << ")\n";
}

template <class Client, class Goal>
bool send(Client& client, const Goal& goal, const std::string& name, double timeout, const std::string& ns = "",
          bool real = false)
{
  client.sendGoal(goal);
  ros::Duration(0.1).sleep();
  confirmIfReal(ns, real, timeout);
  if (!client.waitForResult(ros::Duration(timeout)))
  {
    client.cancelGoal();
    std::cerr << "replay: " << name << ": no result after " << timeout << " s\n";
    return false;
  }
  const auto state = client.getState();
  std::cout << "replay: " << name << ": " << state.toString() << (state.getText().empty() ? "" : " (" + state.getText() + ")")
            << "\n";
  return state == actionlib::SimpleClientGoalState::SUCCEEDED;
}

/// A recorded gripper position as a goal. Measured positions may lie a hair outside the joint's range (the
/// physics' limits are stiff springs, -5e-18 was seen), which the gripper controller rightly refuses: at the
/// limit they mean the limit.
control_msgs::GripperCommandGoal gripperGoal(double position, const GripperRange& range)
{
  control_msgs::GripperCommandGoal goal;
  goal.command.position = std::clamp(position, range.lower, range.upper);
  return goal;
}
}  // namespace

int runReplay(int argc, char** argv)
{
  const Options options(argc, argv, 2, { "mode", "robot", "segment", "speed", "tolerance" }, { "yes" });
  if (options.positional().size() != 1 || !options.has("mode"))
    throw std::invalid_argument("usage: replay BAG --mode fake|physics|real [--robot R] [--segment NAME] [--speed S]");
  const std::string bag = options.positional()[0], mode = options.choice("mode", { "fake", "physics", "real" });
  const Demonstration demo = readDemonstration(bag, options.has("robot") ? std::vector<std::string>{ options.text("robot") }
                                                                         : std::vector<std::string>{});
  if (demo.robots.size() != 1)
    throw DemoError(bag + ": " + std::to_string(demo.robots.size()) + " robots: choose one with --robot");
  RobotTrack track = demo.robots.front();
  bool gripper_only = false;
  double gripper_target = 0.0;
  if (options.has("segment"))
  {
    const Segment segment = findSegment(demo, track, options.text("segment"));
    track = slice(track, segment.start, segment.end);
    gripper_only = segment.gripper;
    gripper_target = segment.gripper_target;
  }

  if (track.gripper_goals.empty())  // a bag without gripper goals (imported): the gripper's own actions
    for (const Segment& segment : segmentPickPlace(demo.robots.front(), demo).segments)
      if (segment.gripper && segment.start >= track.states.front().time && segment.start <= track.states.back().time)
        track.gripper_goals.push_back({ segment.start, segment.gripper_target });

  ros::init(argc, argv, "demo_replay", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const std::string ns = "/" + track.robot + "/";
  vrrw_common::checkWorkspace(
      { track.robot, { ns + "arm_controller/follow_joint_trajectory", ns + "gripper_controller/gripper_cmd" }, {} });
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const std::string running_mode = nh.param<std::string>(ns + "controller/mode", "");
  if (running_mode != mode)
    throw DemoError("replay: --mode " + mode + ", but " + ns + "controller runs in mode '" + running_mode +
                    "' (start the workspace with ./vrrw up SCENE --mode " + mode + ")");
  ReplayOptions replay;
  replay.speed = options.number("speed", 1.0);
  replay.tolerance = options.number("tolerance", 1e-3);
  GripperRange gripper_range;
  limits(nh, track, replay, gripper_range);
  const ReplayPath path = replayPath(track, replay);
  std::cout << "replay: " << track.robot << ", " << track.states.size() << " recorded states -> "
            << path.trajectory.points.size() << " points over " << path.trajectory.duration() << " s; de-jitter: max "
            << path.max_deviation << " rad from the recording (tolerance " << replay.tolerance << "); retiming: x"
            << path.time_scale << (path.limiting.empty() ? " (within the limits)" : " (" + path.limiting + ")") << "\n";

  if (mode == "real" && !options.has("yes"))
  {
    std::cout << "replay: this moves the REAL robot '" << track.robot << "'. Type yes to go on: " << std::flush;
    std::string answer;
    std::getline(std::cin, answer);
    if (answer != "yes")
      throw DemoError("replay: not confirmed; nothing sent");
  }

  ArmClient arm(ns + "arm_controller/follow_joint_trajectory", true);
  GripperClient gripper(ns + "gripper_controller/gripper_cmd", true);
  if (!arm.waitForServer(ros::Duration(10.0)) || !gripper.waitForServer(ros::Duration(10.0)))
    throw DemoError("replay: " + ns + "arm_controller or gripper_controller does not answer");
  if (gripper_only)
    return send(gripper, gripperGoal(gripper_target, gripper_range), "gripper", 10.0) ? 0 : 1;

  // To the recorded start, at a fifth of the velocity limits, and the recorded gripper.
  sensor_msgs::JointStateConstPtr now = ros::topic::waitForMessage<sensor_msgs::JointState>(ns + "joint_states", ros::Duration(5.0));
  if (!now)
    throw DemoError("replay: no " + ns + "joint_states");
  vrrw_trajectory::JointTrajectory approach;
  approach.joint_names = track.joint_names;
  approach.points.resize(2);
  double move_time = 0.5;
  const auto measured_at = vrrw_common::findJoints(now->name, track.joint_names);
  for (std::size_t j = 0; j < track.joint_names.size(); ++j)
  {
    const double from = measured_at && (*measured_at)[j] < now->position.size() ? now->position[(*measured_at)[j]]
                                                                                : path.trajectory.points[0].positions[j];
    approach.points[0].positions.push_back(from);
    approach.points[1].positions.push_back(path.trajectory.points[0].positions[j]);
    move_time = std::max(move_time, 5.0 * std::abs(path.trajectory.points[0].positions[j] - from) / replay.max_velocity[j]);
  }
  approach.points[0].velocities.assign(track.joint_names.size(), 0.0);
  approach.points[1].velocities.assign(track.joint_names.size(), 0.0);
  approach.points[1].time = move_time;
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = vrrw_trajectory::toMsg(approach);
  if (!send(arm, goal, "to the recorded start", move_time + 10.0, ns, mode == "real") ||
      !send(gripper, gripperGoal(track.states.front().gripper, gripper_range), "gripper to the recorded start", 10.0))
    return 1;
  // The controller now holds the recorded start (a demonstration starts from the scene's reset state), so
  // the reset puts the objects back without the arm jumping to an older command.
  if (mode == "physics" && !options.has("segment"))
  {
    std_srvs::Trigger reset;
    vrrw_common::PersistentServices().call("/physics/reset", reset);
    if (!reset.response.success)
      throw DemoError("replay: /physics/reset failed: " + reset.response.message);
    ros::Duration(0.5).sleep();
    std::cout << "replay: physics reset to the scene's start\n";
  }

  // The replay: the trajectory, gripper goals at their recorded (scaled) times, every joint state kept.
  std::mutex mutex;
  std::vector<sensor_msgs::JointState> measured;
  ros::Subscriber states = nh.subscribe<sensor_msgs::JointState>(ns + "joint_states", 10000, [&](const auto& m) {
    std::lock_guard<std::mutex> lock(mutex);
    measured.push_back(*m);
  });
  const ros::Time start = ros::Time::now() + ros::Duration(0.2);
  goal.trajectory = vrrw_trajectory::toMsg(path.trajectory);
  goal.trajectory.header.stamp = start;
  arm.sendGoal(goal);
  confirmIfReal(ns, mode == "real", path.trajectory.duration() + 10.0);
  const double scale = path.time_scale / replay.speed;
  const double t0 = track.states.front().time;
  for (const GripperGoal& g : track.gripper_goals)
  {
    ros::Time::sleepUntil(start + ros::Duration((g.time - t0) * scale));
    gripper.sendGoal(gripperGoal(g.position, gripper_range));
    std::cout << "replay: gripper -> " << g.position << " at t = " << (g.time - t0) * scale << " s\n";
  }
  const double duration = path.trajectory.duration();
  for (double shown = 0; !arm.waitForResult(ros::Duration(1.0));)
    if ((shown = (ros::Time::now() - start).toSec()) < duration + 30.0)
      std::cout << "replay: t = " << std::max(0.0, shown) << " / " << duration << " s\n";
    else
      break;
  if (!track.gripper_goals.empty())
    gripper.waitForResult(ros::Duration(10.0));
  ros::Duration(0.2).sleep();
  states.shutdown();
  const auto result = arm.getState();
  std::cout << "replay: " << result.toString() << (result.getText().empty() ? "" : " (" + result.getText() + ")") << "\n";

  const vrrw_control::TrajectoryInterpolator sent(path.trajectory);
  double max_error = 0.0, sum = 0.0;
  std::size_t count = 0;
  std::lock_guard<std::mutex> lock(mutex);
  for (const auto& state : measured)
  {
    const double t = (state.header.stamp - start).toSec();
    if (t < 0 || t > duration)
      continue;
    const auto at = vrrw_common::findJoints(state.name, track.joint_names);
    if (!at)
      continue;
    const auto expected = sent.sample(t);
    for (std::size_t j = 0; j < track.joint_names.size(); ++j)
    {
      if ((*at)[j] >= state.position.size())
        continue;
      const double e = state.position[(*at)[j]] - expected.positions[j];
      max_error = std::max(max_error, std::abs(e));
      sum += e * e;
      ++count;
    }
  }
  const double rms = count ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
  std::cout << "replay: " << mode << ": " << count / std::max<std::size_t>(1, track.joint_names.size())
            << " joint states during the motion; |q - de-jittered path| max " << max_error << " rad, RMS " << rms
            << " rad\n";
  std::printf("{\"mode\": \"%s\", \"robot\": \"%s\", \"samples\": %zu, \"max_error\": %.3g, \"rms_error\": %.3g, "
              "\"dejitter_max\": %.3g, \"time_scale\": %.6g, \"result\": \"%s\"}\n",
              mode.c_str(), track.robot.c_str(), count, max_error, rms, path.max_deviation, path.time_scale,
              result.toString().c_str());
  return result == actionlib::SimpleClientGoalState::SUCCEEDED ? 0 : 1;
}
}  // namespace vrrw_demos
