// `vrrw demos replay BAG --mode fake|physics|real ...`: a recorded track through the running controllers.
// Stages: read and check the request and the bag; read the running robot's limits; build and check the
// whole replay (nothing is sent before all of it passed); the approach to the recorded start; the
// replay with its gripper goals and progress; the error against the sent path. In physics the tool holds the
// simulation and steps it through the replay at --rtf (lockstep: the same bag replays bit for bit).
#include "replay_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <optional>

#include <sensor_msgs/JointState.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_demos/approach_move.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/replay_path.h>
#include <vrrw_demos/replay_progress.h>
#include <vrrw_demos/ros/robot_controllers.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_demos/tracking_error.h>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_physics/realtime_pacer.h>
#include <vrrw_physics/ros/lockstep_client.h>
#include <vrrw_scene/robot_config.h>

#include <vrrw_demos/ros/demo_bag.h>
#include "segment_report.h"

namespace vrrw_demos
{
namespace
{
/// What the user asked for, checked before anything is read.
struct ReplayRequest
{
  std::string bag, mode;
  std::string robot, segment;  ///< empty: the bag's only robot, the whole track
  ReplayOptions options;
  bool yes = false;
  double rtf = 0.0;  ///< physics: the real-time factor of the lockstep replay (infinity: max); 0 otherwise
};

/// The recorded track to replay and what it is made of.
struct ReplayInput
{
  RobotTrack track;
  bool gripper_only = false;  ///< --segment named a gripper action: one GripperCommand goal
  double gripper_target = 0.0;
  std::vector<Segment> instructions;  ///< for the progress lines
};

/// The running robot: its joints' limits (URDF velocities and positions, the config's accelerations) and
/// the range a gripper goal may name (the actuated joint's URDF limits; none: unbounded).
struct RunningRobot
{
  std::vector<double> min_position, max_position;
  double gripper_lower = -1e9, gripper_upper = 1e9;
};

ReplayRequest parseReplayRequest(int argc, char** argv)
{
  const vrrw_common::Options options(argc, argv, 2, { "mode", "robot", "segment", "speed", "tolerance", "rtf" },
                                     { "yes" });
  options.expectPositional({ "BAG" });
  ReplayRequest request;
  request.bag = options.positional()[0];
  request.mode = options.choice("mode", { "fake", "physics", "real" });
  request.robot = options.text("robot", "");
  request.segment = options.text("segment", "");
  request.options.speed =
      options.number("speed", 1.0, vrrw_common::Range::closed(ReplayBounds::kMinSpeed, ReplayBounds::kMaxSpeed));
  request.options.tolerance =
      options.number("tolerance", 1e-3, vrrw_common::Range::closed(0.0, ReplayBounds::kMaxTolerance, "rad"));
  request.yes = options.flag("yes");
  if (options.has("rtf") && request.mode != "physics")
    throw vrrw_common::OptionError("--rtf: only physics runs on simulated time (--mode physics)");
  if (request.mode == "physics")
  {
    try
    {
      request.rtf = vrrw_physics::parseRealTimeFactor(options.text("rtf", "max"), "--rtf");
    }
    catch (const std::invalid_argument& e)
    {
      throw vrrw_common::OptionError(e.what());
    }
  }
  return request;
}

ReplayInput loadInput(const ReplayRequest& request)
{
  const Demonstration demo =
      readDemonstration(request.bag, request.robot.empty() ? std::vector<std::string>{} : std::vector<std::string>{ request.robot });
  if (demo.robots.size() != 1)
    throw DemoError(request.bag + ": " + std::to_string(demo.robots.size()) + " robots: choose one with --robot");
  ReplayInput input;
  input.track = demo.robots.front();
  input.instructions = segmentPickPlace(demo.robots.front(), demo).segments;
  if (!request.segment.empty())
  {
    const Segment segment = findSegment(demo, input.track, request.segment);
    input.track = slice(input.track, segment.start, segment.end);
    input.gripper_only = segment.gripper;
    input.gripper_target = segment.gripper_target;
  }
  auto& track = input.track;
  if (track.gripper_goals.empty())  // a bag without gripper goals (imported): the gripper's own actions
    for (const Segment& segment : input.instructions)
      if (segment.gripper && segment.start >= track.states.front().time && segment.start <= track.states.back().time)
        track.gripper_goals.push_back({ segment.start, segment.gripper_target });
  return input;
}

/// The running robot's limits into \a options; throws DemoError when the scene's robot is not the recorded one.
RunningRobot runningRobot(ros::NodeHandle& nh, const RobotTrack& track, ReplayOptions& options)
{
  const std::string key = "/scene/robots/" + track.robot + "/";
  std::vector<std::string> joints;
  if (!nh.getParam(key + "arm_joints", joints))
    throw DemoError("replay: the running workspace has no robot '" + track.robot + "' (" + key + "arm_joints)");
  if (joints != track.joint_names)
  {
    std::string recorded, running;
    for (const auto& j : track.joint_names)
      recorded += " " + j;
    for (const auto& j : joints)
      running += " " + j;
    throw DemoError("replay: robot '" + track.robot + "' of the running scene has joints [" + running +
                    " ], the recording has [" + recorded + " ]: not the recorded robot");
  }
  std::string urdf;
  nh.getParam("/robot_description", urdf);
  const auto model = vrrw_kinematics::RobotModel::fromUrdf(urdf);
  const auto acceleration =
      vrrw_scene::loadAccelerationLimits(nh.param<std::string>(key + "config_file", ""), track.robot + "_");
  RunningRobot robot;
  const auto bounded = [](const vrrw_kinematics::JointModel& joint) {
    return joint.type == vrrw_kinematics::JointModel::Type::Revolute ||
           joint.type == vrrw_kinematics::JointModel::Type::Prismatic;
  };
  for (const std::string& name : joints)
  {
    const auto& joint = model.joints()[static_cast<std::size_t>(model.jointIndex(name))];
    options.max_velocity.push_back(joint.max_velocity);
    const auto found = acceleration.find(name);
    options.max_acceleration.push_back(found == acceleration.end() ? 1e9 : found->second);
    robot.min_position.push_back(bounded(joint) ? joint.lower : -1e9);
    robot.max_position.push_back(bounded(joint) ? joint.upper : 1e9);
  }
  const int finger = track.gripper_joint.empty() ? -1 : model.jointIndex(track.gripper_joint);
  if (finger >= 0 && bounded(model.joints()[static_cast<std::size_t>(finger)]))
  {
    robot.gripper_lower = model.joints()[static_cast<std::size_t>(finger)].lower;
    robot.gripper_upper = model.joints()[static_cast<std::size_t>(finger)].upper;
  }
  return robot;
}

/// Every point of the path within the joints' position limits, every gripper goal a finite number. A
/// recorded position may lie a hair outside its range (the physics' limits are stiff springs: -5e-18 was
/// seen), which the controllers rightly refuse: within the de-jitter tolerance it means the limit.
void checkAndClamp(ReplayPath& path, RobotTrack& track, const RunningRobot& robot, double tolerance)
{
  for (auto& point : path.trajectory.points)
    for (std::size_t j = 0; j < point.positions.size(); ++j)
    {
      double& q = point.positions[j];
      if (q < robot.min_position[j] - tolerance || q > robot.max_position[j] + tolerance)
        throw DemoError("replay: joint " + track.joint_names[j] + " at " + std::to_string(q) + " rad (replay t = " +
                        std::to_string(point.time) + " s) is outside its limits [" +
                        std::to_string(robot.min_position[j]) + ", " + std::to_string(robot.max_position[j]) + "]");
      q = std::clamp(q, robot.min_position[j], robot.max_position[j]);
    }
  for (GripperGoal& goal : track.gripper_goals)
  {
    if (!std::isfinite(goal.position))
      throw DemoError("replay: a recorded gripper goal is not a finite position");
    goal.position = std::clamp(goal.position, robot.gripper_lower, robot.gripper_upper);
  }
}

void printProgress(const std::string& line)
{
  std::cout << "replay: " << line << std::endl;
}

/// The gripper goals of the track at their replay times (the recording's, through the retiming).
std::vector<TimedGripperGoal> gripperTimeline(const RobotTrack& track, const ReplayPath& path)
{
  std::vector<TimedGripperGoal> goals;
  for (const GripperGoal& g : track.gripper_goals)
    goals.push_back({ path.replayTime(g.time - track.states.front().time), g.position, 0.0 });
  return goals;
}

/// The joint_states of the robot while the replay runs, on the path's clock.
class StateLog
{
public:
  StateLog(ros::NodeHandle& nh, const std::string& topic, const std::vector<std::string>& joints, const ros::Time& origin)
    : joints_(joints), origin_(origin)
  {
    sub_ = nh.subscribe<sensor_msgs::JointState>(topic, 10000, [this](const sensor_msgs::JointStateConstPtr& m) {
      auto q = vrrw_common::findValues(m->name, m->position, joints_);
      if (!q)
        return;  // not every arm joint: not this arm's state
      std::lock_guard<std::mutex> lock(mutex_);
      states_.push_back({ (m->header.stamp - origin_).toSec(), std::move(*q) });
    });
  }
  /// Waits (wall clock) until the subscription is connected to a publisher.
  bool waitConnected(double seconds)
  {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
         ros::WallDuration(0.005).sleep())
      if (sub_.getNumPublishers() > 0)
        return true;
    return false;
  }
  std::vector<MeasuredState> take()
  {
    sub_.shutdown();
    std::lock_guard<std::mutex> lock(mutex_);
    return std::move(states_);
  }

private:
  std::vector<std::string> joints_;
  ros::Time origin_;
  std::mutex mutex_;
  std::vector<MeasuredState> states_;  ///< PROTECTED BY mutex_ (the spinner's threads append)
  ros::Subscriber sub_;  ///< last: destroyed first (its shutdown waits for a running callback)
};

/// Physics in lockstep for the tool's run: the simulation held (paused) and stepped at the request's real-time
/// factor; let run again at the end when it ran before.
class SimulationHold
{
public:
  SimulationHold(vrrw_common::PersistentServices& services, double rtf)
    : sim_(services, "/physics", lockstepOptions(rtf))
  {
    try
    {
      if (!sim_.waitForPhysics(10.0))
        throw vrrw_common::WorkspaceError("replay: --mode physics: no /physics/step (is the physics node running?)");
      was_running_ = !sim_.paused();
      sim_.pause();
      sim_.now();
    }
    catch (const vrrw_physics::LockstepError& e)
    {
      throw vrrw_common::WorkspaceError(std::string("replay: ") + e.what());
    }
  }
  ~SimulationHold()
  {
    if (!was_running_)
      return;
    try
    {
      sim_.unpause();
    }
    catch (const vrrw_physics::LockstepError& e)
    {
      std::cerr << "replay: the simulation stays paused: " << e.what() << "\n";
    }
  }
  vrrw_physics::LockstepClient& simulation() { return sim_; }

private:
  static vrrw_physics::LockstepOptions lockstepOptions(double rtf)
  {
    vrrw_physics::LockstepOptions options;
    options.rtf = rtf;
    return options;
  }

  vrrw_physics::LockstepClient sim_;
  bool was_running_ = false;
};

bool resetPhysics(RobotControllers& controllers)
{
  // a link of this call's own, closed here while ROS runs (a process-wide one closing at exit, after the
  // spinner and roscpp's own objects, crashed the tool once after its last line)
  vrrw_common::PersistentServices services;
  std_srvs::Trigger call;
  std::string error;
  if (!services.tryCall("/physics/reset", call, &error) || !call.response.success)
  {
    std::cerr << "replay: /physics/reset failed: " << (error.empty() ? call.response.message : error) << "\n";
    return false;
  }
  std::cout << "replay: physics reset to the scene's start" << std::endl;
  return controllers.sleep(0.5);  // the scene settles
}

/// Everything a replay needs, checked.
struct PreparedReplay
{
  ReplayRequest request;
  ReplayInput input;
  ReplayOptions options;  ///< the request's, with the running robot's limits
  RunningRobot robot;
  ReplayPath path;
};

/// Stage 2 on the request and the recording of stage 1: the running robot and the whole replay.
PreparedReplay prepare(ReplayRequest request, ReplayInput input, ros::NodeHandle& nh)
{
  PreparedReplay r{ std::move(request), std::move(input), {}, {}, {} };
  const RobotTrack& track = r.input.track;
  const std::string ns = "/" + track.robot + "/";
  const std::string running_mode = nh.param<std::string>(ns + "controller/mode", "");
  if (running_mode != r.request.mode)
    throw DemoError("replay: --mode " + r.request.mode + ", but " + ns + "controller runs in mode '" + running_mode +
                    "' (start the workspace with ./vrrw up SCENE --mode " + r.request.mode + ")");
  r.options = r.request.options;
  r.robot = runningRobot(nh, track, r.options);
  r.path = replayPath(track, r.options);
  checkAndClamp(r.path, r.input.track, r.robot, r.options.tolerance);
  std::cout << "replay: " << track.robot << ", " << track.states.size() << " recorded states over "
            << track.states.back().time - track.states.front().time << " s -> " << r.path.trajectory.points.size()
            << " points over " << r.path.trajectory.duration() << " s at speed " << r.options.speed
            << "; de-jitter: max " << r.path.max_deviation << " rad from the recording (tolerance "
            << r.options.tolerance << "); timing: " << r.path.retimingSummary() << std::endl;
  return r;
}

/// Stage 3: to the recorded start, slowly, with the recorded gripper; in physics the scene's reset then.
bool approach(const PreparedReplay& r, RobotControllers& controllers)
{
  const RobotTrack& track = r.input.track;
  const double gripper = std::clamp(track.states.front().gripper, r.robot.gripper_lower, r.robot.gripper_upper);
  const ArmMotion move{ "to the recorded start",
                        approachMove(track.joint_names, controllers.measuredArm(track.joint_names, 5.0),
                                     r.path.trajectory.points.front().positions, r.options.max_velocity),
                        ros::Time(), { { 0.0, gripper, 0.0 } } };
  const GoalOutcome outcome = controllers.runArm(move, 10.0, [](const MotionProgress& p) {
    printProgress(progressText(p.name, p.elapsed, p.duration) + (p.real ? " (real arm)" : ""));
  });
  std::cout << "replay: to the recorded start: " << outcome.text() << std::endl;
  // The controller now holds the recorded start (a demonstration starts from the scene's reset state), so
  // the reset puts the objects back without the arm jumping to an older command.
  return outcome.succeeded() && (r.request.mode != "physics" || !r.request.segment.empty() || resetPhysics(controllers));
}

/// Stages 4 and 5: the replay with its gripper goals and progress, every joint state kept; then the error
/// against what the controller was sent (its own spline), as a line and as JSON.
int replayAndMeasure(const PreparedReplay& r, RobotControllers& controllers, ros::NodeHandle& nh)
{
  const RobotTrack& track = r.input.track;
  const ros::Time start = controllers.now() + ros::Duration(0.2);
  StateLog log(nh, "/" + track.robot + "/joint_states", track.joint_names, start);
  if (!log.waitConnected(10.0))  // in lockstep the first step publishes: nothing may be missed
    throw vrrw_common::WorkspaceError("replay: /" + track.robot + "/joint_states: no publisher within 10 s");
  const ArmMotion replay{ "replay", r.path.trajectory, start, gripperTimeline(track, r.path) };
  for (const auto& g : replay.gripper_goals)
    std::cout << "replay: gripper -> " << g.position << " at t = " << g.time << " s" << std::endl;
  const GoalOutcome outcome = controllers.runArm(replay, 30.0, [&](const MotionProgress& p) {
    printProgress(progressLine(r.path, r.input.instructions, track.states.front().time, p.elapsed) +
                  (p.real ? " (real arm)" : ""));
  });
  controllers.sleep(0.2);  // the last states arrive
  std::cout << "replay: " << outcome.text() << std::endl;

  const vrrw_control::TrajectoryInterpolator sent(r.path.trajectory);
  const double duration = r.path.trajectory.duration();
  const TrackingError error =
      trackingError(log.take(), [&](double t) { return sent.sample(t).positions; }, duration);
  std::cout << "replay: " << r.request.mode << ": " << error.states
            << " joint states during the motion; |q - de-jittered path| max " << error.max << " rad, RMS " << error.rms
            << " rad" << std::endl;
  std::printf("{\"mode\": \"%s\", \"robot\": \"%s\", \"samples\": %zu, \"max_error\": %.3g, \"rms_error\": %.3g, "
              "\"dejitter_max\": %.3g, \"time_scale\": %.6g, \"recorded\": %.6g, \"duration\": %.6g, "
              "\"stretches\": %zu, \"result\": \"%s\"}\n",
              r.request.mode.c_str(), track.robot.c_str(), error.values, error.max, error.rms, r.path.max_deviation,
              r.path.time_scale, track.states.back().time - track.states.front().time, duration,
              r.path.stretches.size(), outcome.state.c_str());
  std::fflush(stdout);
  return outcome.succeeded() ? 0 : 1;
}
}  // namespace

int runReplay(int argc, char** argv, const std::atomic<bool>& interrupted)
{
  // Stage 1, before any contact with ROS: the request and the recording.
  ReplayRequest request = parseReplayRequest(argc, argv);
  ReplayInput input = loadInput(request);
  ros::init(argc, argv, "demo_replay", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const vrrw_common::ToolNode node_registration;
  const std::string ns = "/" + input.track.robot + "/";
  vrrw_common::checkWorkspace(
      { input.track.robot, { ns + "arm_controller/follow_joint_trajectory", ns + "gripper_controller/gripper_cmd" }, {} });
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const PreparedReplay r = prepare(std::move(request), std::move(input), nh);  // nothing is sent before all passed
  if (r.request.mode == "real" && !r.request.yes &&
      !operatorSaysYes("replay: this moves the REAL robot '" + r.input.track.robot + "'.", std::cin, std::cout))
    throw DemoError("replay: not confirmed; nothing sent");
  RobotControllers controllers(r.input.track.robot, r.request.mode == "real", &interrupted);
  controllers.connect(10.0);
  vrrw_common::PersistentServices links;  // the simulation's, closed before ROS stops
  std::optional<SimulationHold> hold;
  if (r.request.mode == "physics")
  {
    hold.emplace(links, r.request.rtf);
    controllers.holdSimulation(hold->simulation());
  }
  if (r.input.gripper_only)
  {
    const auto outcome = controllers.runGripper(
        std::clamp(r.input.gripper_target, r.robot.gripper_lower, r.robot.gripper_upper), 0.0, 10.0);
    std::cout << "replay: gripper: " << outcome.text() << std::endl;
    return outcome.succeeded() ? 0 : 1;
  }
  return approach(r, controllers) ? replayAndMeasure(r, controllers, nh) : 1;
}
}  // namespace vrrw_demos
