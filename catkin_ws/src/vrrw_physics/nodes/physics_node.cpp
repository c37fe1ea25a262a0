// physics_node: steps a vrrw_physics::PhysicsWorld of the scene in ~scene and wires it to ROS.
//   publishes  /<robot>/joint_states, /joint_states (all robots), tf world -> <object>, /clock
//              (~publish_clock), ~errors (std_msgs/String: rejected input, guard trips)
//   subscribes /<robot>/drive_targets (sensor_msgs/JointState: name, position, optional velocity),
//              ~hand_pose (geometry_msgs/PoseStamped: the kinematic hand),
//              ~spring_target (vrrw_physics/SpringTarget: moves an attached operator spring)
//   services   ~pause ~resume ~step ~reset (std_srvs/Trigger), ~set_mode, ~set_gains, ~set_spring,
//              ~set_object_pose (vrrw_physics/*)
#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/SetGains.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_physics/SetSpring.h>
#include <vrrw_physics/SpringTarget.h>
#include <vrrw_scene/scene_loader.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>

#include <functional>
#include <memory>

namespace
{
using vrrw_physics::PhysicsWorld;

Eigen::Isometry3d toEigen(const geometry_msgs::Pose& p)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
  const Eigen::Quaterniond q(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
  if (q.norm() < 1e-9)
    throw vrrw_physics::InputError("pose: orientation quaternion is zero");
  t.rotate(q.normalized());
  return t;
}

class PhysicsNode
{
public:
  PhysicsNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const vrrw_scene::Scene& scene,
              const vrrw_physics::WorldOptions& options)
    : world_(scene, options)
  {
    pnh.param("realtime", realtime_, true);
    pnh.param("publish_clock", publish_clock_, false);
    pnh.param("paused", paused_, false);
    double rate = 100.0;
    pnh.param("publish_rate", rate, 100.0);
    publish_every_ = std::max(1, int(std::lround(1.0 / (rate * options.dt))));
    std::string mode;
    pnh.param<std::string>("mode", mode, "rigid");
    for (const std::string& robot : world_.robotNames())
    {
      world_.setMode(robot, vrrw_physics::parseDriveMode(mode));
      robot_states_.push_back(nh.advertise<sensor_msgs::JointState>(robot + "/joint_states", 10));
      targets_.push_back(nh.subscribe<sensor_msgs::JointState>(
          robot + "/drive_targets", 10, [this, robot](const sensor_msgs::JointStateConstPtr& msg) { onTargets(robot, *msg); }));
    }
    all_states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
    errors_ = pnh.advertise<std_msgs::String>("errors", 10, true);
    if (publish_clock_)
      clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    hand_ = pnh.subscribe<geometry_msgs::PoseStamped>("hand_pose", 10, [this](const geometry_msgs::PoseStampedConstPtr& msg) {
      guarded("hand_pose", [&] { world_.setHandPose(toEigen(msg->pose)); });
    });
    spring_target_ = pnh.subscribe<vrrw_physics::SpringTarget>(
        "spring_target", 10, [this](const vrrw_physics::SpringTargetConstPtr& msg) {
          guarded("spring_target", [&] {
            world_.moveSpring(msg->id, toEigen(msg->target), Eigen::Vector3d(msg->velocity.x, msg->velocity.y, msg->velocity.z));
          });
        });
    services_.push_back(pnh.advertiseService("pause", &PhysicsNode::onPause, this));
    services_.push_back(pnh.advertiseService("resume", &PhysicsNode::onResume, this));
    services_.push_back(pnh.advertiseService("step", &PhysicsNode::onStep, this));
    services_.push_back(pnh.advertiseService("reset", &PhysicsNode::onReset, this));
    services_.push_back(pnh.advertiseService("set_mode", &PhysicsNode::onSetMode, this));
    services_.push_back(pnh.advertiseService("set_gains", &PhysicsNode::onSetGains, this));
    services_.push_back(pnh.advertiseService("set_spring", &PhysicsNode::onSetSpring, this));
    services_.push_back(pnh.advertiseService("set_object_pose", &PhysicsNode::onSetObjectPose, this));
  }

  void run()
  {
    ros::WallTime start = ros::WallTime::now();
    double started_at = world_.time();
    publish();
    while (ros::ok())
    {
      ros::spinOnce();
      if (paused_)
      {
        ros::WallDuration(0.005).sleep();
        start = ros::WallTime::now();
        started_at = world_.time();
        continue;
      }
      advance();
      if (realtime_)
      {
        const ros::WallTime due = start + ros::WallDuration(world_.time() - started_at);
        const ros::WallTime now = ros::WallTime::now();
        if (due > now)
          (due - now).sleep();
        else if ((now - due).toSec() > 0.1)
        {
          start = now;  // fell behind by more than 100 ms: do not try to catch up
          started_at = world_.time();
        }
      }
    }
  }

private:
  void advance()
  {
    if (!world_.step())
      report(world_.lastError());
    ++steps_;
    if (publish_clock_)
    {
      rosgraph_msgs::Clock clock;
      clock.clock = ros::Time(world_.time());
      clock_.publish(clock);
    }
    if (steps_ % std::uint64_t(publish_every_) == 0)
      publish();
  }

  ros::Time stamp() const
  {
    return publish_clock_ ? ros::Time(world_.time()) : ros::Time::now();
  }

  void publish()
  {
    const ros::Time now = stamp();
    sensor_msgs::JointState all;
    all.header.stamp = now;
    const auto robots = world_.robotNames();
    for (std::size_t r = 0; r < robots.size(); ++r)
    {
      const vrrw_physics::JointStates s = world_.jointStates(robots[r]);
      sensor_msgs::JointState msg;
      msg.header.stamp = now;
      msg.name = s.name;
      msg.position = s.position;
      msg.velocity = s.velocity;
      msg.effort = s.effort;
      robot_states_[r].publish(msg);
      all.name.insert(all.name.end(), s.name.begin(), s.name.end());
      all.position.insert(all.position.end(), s.position.begin(), s.position.end());
      all.velocity.insert(all.velocity.end(), s.velocity.begin(), s.velocity.end());
      all.effort.insert(all.effort.end(), s.effort.begin(), s.effort.end());
    }
    all_states_.publish(all);
    std::vector<geometry_msgs::TransformStamped> frames;
    for (const std::string& object : world_.objectNames())
    {
      const Eigen::Isometry3d pose = world_.objectPose(object);
      const Eigen::Quaterniond q(pose.rotation());
      geometry_msgs::TransformStamped t;
      t.header.stamp = now;
      t.header.frame_id = "world";
      t.child_frame_id = object;
      t.transform.translation.x = pose.translation().x();
      t.transform.translation.y = pose.translation().y();
      t.transform.translation.z = pose.translation().z();
      t.transform.rotation.w = q.w();
      t.transform.rotation.x = q.x();
      t.transform.rotation.y = q.y();
      t.transform.rotation.z = q.z();
      frames.push_back(t);
    }
    if (!frames.empty())
      tf_.sendTransform(frames);
  }

  void report(const std::string& message)
  {
    ROS_ERROR_STREAM_THROTTLE(1.0, message);
    std_msgs::String msg;
    msg.data = message;
    errors_.publish(msg);
  }

  /// Runs `call`; an InputError (or a bad mode) becomes one error line; returns the message or "".
  std::string guarded(const std::string& what, const std::function<void()>& call)
  {
    try
    {
      call();
      return "";
    }
    catch (const std::invalid_argument& e)
    {
      const std::string message = what + ": " + e.what();
      report(message);
      return message;
    }
  }

  template <class Response>
  bool answer(Response& res, const std::string& error)
  {
    res.success = error.empty();
    res.message = error.empty() ? "ok" : error;
    return true;
  }

  void onTargets(const std::string& robot, const sensor_msgs::JointState& msg)
  {
    guarded("/" + robot + "/drive_targets", [&] { world_.setDriveTargets(robot, msg.name, msg.position, msg.velocity); });
  }

  bool onPause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res)
  {
    paused_ = true;
    return answer(res, "");
  }

  bool onResume(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res)
  {
    paused_ = false;
    return answer(res, "");
  }

  bool onStep(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res)
  {
    if (!paused_)
      return answer(res, "step: pause the simulation first");
    advance();
    publish();
    return answer(res, "");
  }

  bool onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res)
  {
    world_.reset();
    publish();
    return answer(res, "");
  }

  bool onSetMode(vrrw_physics::SetMode::Request& req, vrrw_physics::SetMode::Response& res)
  {
    return answer(res, guarded("set_mode", [&] { world_.setMode(req.robot, vrrw_physics::parseDriveMode(req.mode)); }));
  }

  bool onSetGains(vrrw_physics::SetGains::Request& req, vrrw_physics::SetGains::Response& res)
  {
    return answer(res, guarded("set_gains", [&] {
                    world_.setGains(req.robot, req.joints, req.stiffness, req.damping, req.max_force);
                  }));
  }

  bool onSetSpring(vrrw_physics::SetSpring::Request& req, vrrw_physics::SetSpring::Response& res)
  {
    return answer(res, guarded("set_spring", [&] {
                    if (req.release)
                      return world_.releaseSpring(req.id);
                    vrrw_physics::OperatorSpring spring;
                    spring.body = req.body;
                    spring.point = Eigen::Vector3d(req.point.x, req.point.y, req.point.z);
                    spring.target = toEigen(req.target);
                    spring.stiffness = req.stiffness;
                    spring.damping = req.damping;
                    spring.angular_stiffness = req.angular_stiffness;
                    spring.angular_damping = req.angular_damping;
                    if (req.max_force > 0.0)
                      spring.max_force = req.max_force;
                    world_.attachSpring(req.id, spring);
                  }));
  }

  bool onSetObjectPose(vrrw_physics::SetObjectPose::Request& req, vrrw_physics::SetObjectPose::Response& res)
  {
    return answer(res, guarded("set_object_pose", [&] { world_.setObjectPose(req.object, toEigen(req.pose)); }));
  }

  PhysicsWorld world_;
  bool realtime_ = true;
  bool publish_clock_ = false;
  bool paused_ = false;
  int publish_every_ = 10;
  std::uint64_t steps_ = 0;
  std::vector<ros::Publisher> robot_states_;
  std::vector<ros::Subscriber> targets_;
  ros::Publisher all_states_, errors_, clock_;
  ros::Subscriber hand_, spring_target_;
  std::vector<ros::ServiceServer> services_;
  tf2_ros::TransformBroadcaster tf_;
};
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
  vrrw_physics::WorldOptions options;
  pnh.param("dt", options.dt, options.dt);
  pnh.param("solver_iterations", options.solver_iterations, options.solver_iterations);
  pnh.param("gravity_compensation", options.gravity_compensation, options.gravity_compensation);
  std::string scheme;
  pnh.param<std::string>("drives", scheme, "constraint");
  options.drive_scheme =
      scheme == "stable_pd" ? vrrw_physics::DriveScheme::StablePd : vrrw_physics::DriveScheme::Constraint;
  try
  {
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(scene_name);
    PhysicsNode node(nh, pnh, scene, options);
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
