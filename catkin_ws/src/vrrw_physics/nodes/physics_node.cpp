// physics_node: steps a vrrw_physics::PhysicsWorld of the scene in ~scene and wires it to ROS.
//   publishes  /<robot>/joint_states, /joint_states (all robots), tf world -> <object>, /clock
//              (~publish_clock), ~contacts (vrrw_physics/Contacts), ~errors (std_msgs/String, latched:
//              rejected input, guard trips, robots whose targets stopped, hands removed)
//   subscribes /<robot>/drive_targets (sensor_msgs/JointState: name, position, optional velocity and effort),
//              ~hand (vrrw_physics/Hand), ~spring_target (vrrw_physics/SpringTarget)
//   services   ~pause ~resume ~step ~reset (std_srvs/Trigger), ~set_mode, ~set_gains, ~set_spring,
//              ~set_object_pose (vrrw_physics/*)
#include <vrrw_physics/Hand.h>
#include <vrrw_physics/SetGains.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_physics/SpringTarget.h>
#include <vrrw_physics/realtime_pacer.h>
#include <vrrw_physics/report_throttle.h>
#include <vrrw_scene/scene_loader.h>

#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>

#include <functional>

#include "physics_messages.h"

namespace
{
using vrrw_physics::PhysicsWorld;
using vrrw_physics::toEigen;

class PhysicsNode
{
public:
  PhysicsNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const vrrw_scene::Scene& scene,
              const vrrw_physics::WorldOptions& options, double publish_rate)
    : world_(scene, options), publish_every_(std::max(1, int(std::lround(1.0 / (publish_rate * options.dt)))))
  {
    pnh.param("realtime", realtime_, true);
    pnh.param("publish_clock", publish_clock_, false);
    pnh.param("paused", paused_, false);
    for (const std::string& robot : world_.robotNames())
    {
      robot_states_.push_back(nh.advertise<sensor_msgs::JointState>(robot + "/joint_states", 10));
      subscribers_.push_back(nh.subscribe<sensor_msgs::JointState>(
          robot + "/drive_targets", 10, [this, robot](const sensor_msgs::JointStateConstPtr& m) {
            guarded("/" + robot + "/drive_targets",
                    [&] { world_.setDriveTargets(robot, m->name, m->position, m->velocity, m->effort); });
          }));
    }
    all_states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
    contacts_ = pnh.advertise<vrrw_physics::Contacts>("contacts", 10);
    errors_ = pnh.advertise<std_msgs::String>("errors", 10, true);
    if (publish_clock_)
      clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    subscribers_.push_back(pnh.subscribe<vrrw_physics::Hand>("hand", 100, [this](const vrrw_physics::HandConstPtr& m) {
      guarded("hand", [&] { world_.operatorInput().setHand(m->id, toEigen(m->pose), m->radius); });
    }));
    subscribers_.push_back(pnh.subscribe<vrrw_physics::SpringTarget>(
        "spring_target", 10, [this](const vrrw_physics::SpringTargetConstPtr& m) {
          guarded("spring_target",
                  [&] { world_.operatorInput().moveSpring(m->id, toEigen(m->target), toEigen(m->velocity)); });
        }));
    trigger(pnh, "pause", [this] { paused_ = true; });
    trigger(pnh, "resume", [this] { paused_ = false; });
    trigger(pnh, "step", [this] {
      if (!paused_)
        throw vrrw_physics::InputError("pause the simulation first");
      advance();
      publish();
    });
    trigger(pnh, "reset", [this] {
      world_.reset();
      publish();
    });
    service<vrrw_physics::SetMode>(pnh, "set_mode", [this](auto& req) {
      world_.setMode(req.robot, vrrw_physics::parseDriveMode(req.mode));
    });
    service<vrrw_physics::SetGains>(pnh, "set_gains", [this](auto& req) {
      world_.setGains(req.robot, req.joints, req.stiffness, req.damping, req.max_force);
    });
    service<vrrw_physics::SetSpring>(pnh, "set_spring", [this](auto& req) {
      if (req.release)
        world_.operatorInput().releaseSpring(req.id);
      else
        world_.operatorInput().attachSpring(req.id, vrrw_physics::toSpring(req));
    });
    service<vrrw_physics::SetObjectPose>(pnh, "set_object_pose",
                                         [this](auto& req) { world_.setObjectPose(req.object, toEigen(req.pose)); });
  }

  void run()
  {
    publish();
    pacer_.restart(world_.time());
    while (ros::ok())
    {
      ros::spinOnce();
      if (paused_ || world_.stopped())
      {
        ros::WallDuration(0.005).sleep();
        pacer_.restart(world_.time());
        continue;
      }
      advance();
      if (realtime_)
        ros::WallDuration(pacer_.wait(world_.time())).sleep();
    }
  }

private:
  void advance()
  {
    world_.step();
    for (const std::string& line : world_.takeReports())
      report("world", line, world_.stopped());
    if (publish_clock_)
    {
      rosgraph_msgs::Clock clock;
      clock.clock = ros::Time(world_.time());
      clock_.publish(clock);
    }
    if (world_.steps() % std::uint64_t(publish_every_) == 0)
      publish();
  }

  void publish()
  {
    const ros::Time now = publish_clock_ ? ros::Time(world_.time()) : ros::Time::now();
    sensor_msgs::JointState all;
    all.header.stamp = now;
    const auto robots = world_.robotNames();
    for (std::size_t r = 0; r < robots.size(); ++r)
    {
      const sensor_msgs::JointState msg = vrrw_physics::toMsg(world_.jointStates(robots[r]), now);
      robot_states_[r].publish(msg);
      vrrw_physics::append(msg, all);
    }
    all_states_.publish(all);
    std::vector<geometry_msgs::TransformStamped> frames;
    for (const std::string& object : world_.objectNames())
      frames.push_back(vrrw_physics::toTransform(world_.objectPose(object), object, now));
    if (!frames.empty())
      tf_.sendTransform(frames);
    contacts_.publish(vrrw_physics::toMsg(world_.contacts(), now));
  }

  /// One line per `source` per second at most (ReportThrottle), unless `always`.
  void report(const std::string& source, const std::string& message, bool always = false)
  {
    std_msgs::String msg;
    msg.data = always ? message : throttle_.admit(source, message, ros::WallTime::now().toSec());
    if (!msg.data.empty())
      errors_.publish(msg);
    ROS_ERROR_STREAM_COND(!msg.data.empty(), msg.data);
  }

  /// Runs `call`; an InputError (or a bad mode) becomes one error line; returns the message or "".
  std::string guarded(const std::string& source, const std::function<void()>& call)
  {
    try
    {
      call();
      return "";
    }
    catch (const std::invalid_argument& e)
    {
      const std::string message = source + ": " + e.what();
      report(source, message);
      return message;
    }
  }

  template <class Srv, class Call>
  void service(ros::NodeHandle& pnh, const std::string& name, Call call)
  {
    services_.push_back(pnh.advertiseService<typename Srv::Request, typename Srv::Response>(
        name, [this, name, call](typename Srv::Request& req, typename Srv::Response& res) {
          const std::string error = guarded(name, [&] { call(req); });
          res.success = error.empty();
          res.message = error.empty() ? "ok" : error;
          return true;
        }));
  }

  void trigger(ros::NodeHandle& pnh, const std::string& name, const std::function<void()>& call)
  {
    service<std_srvs::Trigger>(pnh, name, [call](auto&) { call(); });
  }

  PhysicsWorld world_;
  int publish_every_;
  bool realtime_ = true;
  bool publish_clock_ = false;
  bool paused_ = false;
  vrrw_physics::RealtimePacer pacer_;
  vrrw_physics::ReportThrottle throttle_;
  std::vector<ros::Publisher> robot_states_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher all_states_, contacts_, errors_, clock_;
  std::vector<ros::ServiceServer> services_;
  tf2_ros::TransformBroadcaster tf_;
};

vrrw_physics::WorldOptions readOptions(ros::NodeHandle& pnh)
{
  vrrw_physics::WorldOptions options;
  pnh.param("dt", options.dt, options.dt);
  pnh.param("solver_iterations", options.solver_iterations, options.solver_iterations);
  pnh.param("gravity_compensation", options.gravity_compensation, options.gravity_compensation);
  pnh.param("target_timeout", options.target_timeout, options.target_timeout);
  pnh.param("hand_timeout", options.hand_timeout, options.hand_timeout);
  options.mode = vrrw_physics::parseDriveMode(pnh.param<std::string>("mode", "rigid"));
  options.drive_scheme = vrrw_physics::parseDriveScheme(pnh.param<std::string>("drives", "constraint"));
  return options;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "physics_node");
  ros::NodeHandle nh, pnh("~");
  std::string scene_name;
  if (!pnh.getParam("scene", scene_name))
  {
    ROS_FATAL("physics_node: ~scene: missing (a shipped scene name or a scene YAML path)");
    return 2;
  }
  try
  {
    const vrrw_physics::WorldOptions options = readOptions(pnh);
    const double publish_rate = pnh.param("publish_rate", 100.0);
    if (!(publish_rate > 0.0))
      throw std::invalid_argument("~publish_rate: must be > 0 Hz");
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(scene_name);
    PhysicsNode node(nh, pnh, scene, options, publish_rate);
    ROS_INFO_STREAM("physics_node: scene " << scene.name << ", " << scene.robots.size() << " robots, "
                                           << scene.objects.size() << " objects, dt " << options.dt << " s");
    node.run();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM("physics_node: " << e.what());
    return 1;
  }
  return 0;
}
