// PhysicsNode: stepping, controllers, stamped operator input, /physics/step, what observers get.
#include "physics_node.h"

#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Header.h>
#include <std_msgs/String.h>

#include <urdf_parser/urdf_parser.h>

#include <cmath>

#include "physics_messages.h"

namespace vrrw_physics
{
namespace
{
/// Most stamped inputs waiting for their time: a flood of future stamps is refused, not stored.
constexpr std::size_t kMaxPendingInput = 10000;
/// Messages an observer may fall behind on each topic (20 s of states at 50 Hz): at rtf max a slow observer gets
/// every one, later, so what it counts is the same each run.
constexpr std::uint32_t kObserverQueue = 1000;
/// Longest /physics/step request (simulated s).
constexpr double kMaxStep = 600.0;
/// Wall s: paced, the steps run in bursts of about this long, then wait once. One wake-up per 1 ms step cost
/// the node 0.1 CPU s per second; 5 ms keeps the simulation within 5 ms of the wall clock, 10 times finer than
/// observers see it (50 Hz) and below what a person at the markers notices.
constexpr double kPaceBurst = 0.005;

/// Wakes the stepping thread from its wait on the global queue (a step request arrived).
struct Wake : ros::CallbackInterface
{
  CallResult call() override { return Success; }
};

int everySteps(double rate, double dt)
{
  return rate > 0.0 ? std::max(1, int(std::lround(1.0 / (rate * dt)))) : 1;
}
}  // namespace

PhysicsNode::PhysicsNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const vrrw_scene::Scene& scene,
                         const WorldOptions& world_options, const NodeOptions& options)
  : world_(scene, world_options)
  , options_(options)
  , publish_every_(everySteps(options.publish_rate, world_options.dt))
  , clock_every_(everySteps(options.clock_rate, world_options.dt))
  , paused_(options.paused)
  , pacer_(0.1, options.rtf, kPaceBurst)
  , controllers_(world_, scene, options.controller, [this] { return ros::Time(world_.time()); })
{
  // Latched, as /clock: a node that connects while the simulation waits gets where and when it waits.
  for (const std::string& robot : world_.robotNames())
    robot_states_.push_back(nh.advertise<sensor_msgs::JointState>(robot + "/joint_states", kObserverQueue, true));
  if (options.robot_tf && !scene.robots.empty())
  {
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);  // PhysicsWorld parsed it already
    for (const std::string& robot : world_.robotNames())
      robot_frames_.emplace_back(*model, world_.jointStates(robot).name);
  }
  all_states_ = nh.advertise<sensor_msgs::JointState>("joint_states", kObserverQueue, true);
  contacts_ = pnh.advertise<Contacts>("contacts", kObserverQueue);
  tf_ = nh.advertise<tf2_msgs::TFMessage>("/tf", kObserverQueue);  // (tf2_ros' broadcaster queues 100)
  errors_ = pnh.advertise<std_msgs::String>("errors", 10, true);
  clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10, true);
  input_queued_ = pnh.advertise<std_msgs::Header>("input_queued", 100);
  subscribers_.push_back(pnh.subscribe("hand", 100, &PhysicsNode::onHand, this));
  subscribers_.push_back(pnh.subscribe("spring_target", 100, &PhysicsNode::onSpringTarget, this));
  advertiseServices(pnh);
  ros::AdvertiseServiceOptions step;
  step.init<Step::Request, Step::Response>(pnh.resolveName("step"),
                                           [this](Step::Request& req, Step::Response& res) { return serveStep(req, res); });
  step.callback_queue = &step_queue_;
  step_service_ = pnh.advertiseService(step);
  step_thread_ = std::thread([this] {
    while (ros::ok())
      step_queue_.callAvailable(ros::WallDuration(0.1));
  });
  for (const std::string& line : controllers_.describe())
    ROS_INFO_STREAM("physics_node: controller of " << line << " runs in lockstep");
}

PhysicsNode::~PhysicsNode()
{
  ros::shutdown();
  {
    std::lock_guard<std::mutex> lock(step_mutex_);
    if (step_)
      step_->finished = true;
  }
  step_done_.notify_all();
  if (step_thread_.joinable())
    step_thread_.join();
}

void PhysicsNode::run()
{
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  bool running = false;
  advance();  // a paused start waits at the first step: time 0 is no valid ROS time (nodes wait for a later one)
  stopped();
  while (ros::ok())
  {
    bool stepping, nothing_to_step;
    double request_rtf = 0.0;
    {
      std::lock_guard<std::mutex> lock(step_mutex_);
      stepping = step_ && !step_->finished;
      nothing_to_step = stepping && step_->steps == 0;
      request_rtf = stepping ? step_->rtf : 0.0;
    }
    if (stepping && (nothing_to_step || world_.stopped()))
    {
      runStepRequest(false);  // it ends here
      continue;
    }
    if (world_.stopped() || (paused_ && !stepping))
    {
      if (running)
        stopped();
      running = false;
      queue.callAvailable(ros::WallDuration(0.01));
      continue;
    }
    if (!running)
    {
      pacer_.setRtf(request_rtf > 0.0 ? request_rtf : options_.rtf);  // a step request's own, or the node's
      pacer_.restart(world_.time());
    }
    running = true;
    advance();
    if (stepping && runStepRequest(true))
      running = false;  // it published where it stopped
    for (double wait = pacer_.wait(world_.time());; wait = pacer_.wait(world_.time()))
    {
      queue.callAvailable(ros::WallDuration(wait));
      if (wait <= 0.0)
        break;
    }
  }
}

void PhysicsNode::advance()
{
  applyDueInput();
  for (const std::string& line : controllers_.update(ros::Duration(world_.options().dt)))
    report("controllers", line);
  world_.step();
  for (const std::string& line : world_.takeReports())
    report("world", line, world_.stopped());
  if (world_.stopped())
    controllers_.interrupt("the simulation stopped: " + world_.lastError());
  if (world_.steps() % std::uint64_t(clock_every_) == 0)
    publishClock();
  if (world_.steps() % std::uint64_t(publish_every_) == 0)
    publishStates();
}

void PhysicsNode::stopped()
{
  publishClock();
  publishStates();
}

bool PhysicsNode::runStepRequest(bool stepped)
{
  std::lock_guard<std::mutex> lock(step_mutex_);
  StepRequest& r = *step_;
  r.done += stepped ? 1 : 0;
  const bool idle = controllers_.idle();
  if (world_.stopped() && r.done == 0)
    r.refused = "the world stopped (" + world_.lastError() + "): call /physics/reset";
  if (world_.stopped() || r.done >= r.steps || (stepped && r.until_idle && idle))
  {
    r.finished = true;
    r.idle = idle;
    r.time = world_.time();
    if (r.done > 0 || world_.stopped())  // a query (duration 0) changes nothing: the state here is published
      stopped();
    step_done_.notify_all();
  }
  return r.finished;
}

bool PhysicsNode::serveStep(Step::Request& req, Step::Response& res)
{
  std::unique_lock<std::mutex> lock(step_mutex_);
  res.success = false;
  if (!paused_)
    res.message = "the simulation runs: pause it first (/physics/pause)";
  else if (step_)
    res.message = "a step request is running";
  else if (!(req.duration >= 0.0 && req.duration <= kMaxStep))
    res.message = "duration: " + std::to_string(req.duration) + " outside [0, 600] s";
  else if (!(req.rtf >= 0.0))
    res.message = "rtf: " + std::to_string(req.rtf) + " is not 0 (the node's), a positive number or inf";
  if (!res.message.empty())
    return true;
  step_ = std::make_unique<StepRequest>();
  step_->steps = std::uint64_t(std::llround(req.duration / world_.options().dt));
  step_->until_idle = req.until_idle;
  step_->rtf = req.rtf;
  ros::getGlobalCallbackQueue()->addCallback(boost::make_shared<Wake>());
  step_done_.wait(lock, [this] { return step_->finished; });
  res.success = step_->refused.empty();
  res.message = res.success ? "stepped " + std::to_string(step_->done) + " steps" : step_->refused;
  res.time = ros::Time(step_->time);
  res.steps = std::uint32_t(step_->done);
  res.idle = step_->idle;
  step_.reset();
  return true;
}

void PhysicsNode::publishClock()
{
  if (clock_at_ == world_.steps())
    return;
  clock_at_ = world_.steps();
  rosgraph_msgs::Clock clock;
  clock.clock = ros::Time(world_.time());
  clock_.publish(clock);
}

void PhysicsNode::publishStates()
{
  if (states_at_ == world_.steps())
    return;
  states_at_ = world_.steps();
  const ros::Time now(world_.time());
  sensor_msgs::JointState all;
  all.header.stamp = now;
  // one tf message per state: the robots' moving frames (robot_state_publisher's part) and the objects'
  tf2_msgs::TFMessage frames;
  const auto robots = world_.robotNames();
  for (std::size_t r = 0; r < robots.size(); ++r)
  {
    const JointStates states = world_.jointStates(robots[r]);
    const sensor_msgs::JointState msg = toMsg(states, now);
    robot_states_[r].publish(msg);
    append(msg, all);
    if (r < robot_frames_.size())
      for (const JointFrames::Frame& f : robot_frames_[r].at(states.position))
        frames.transforms.push_back(toTransform(f.pose, f.parent, f.child, now));
  }
  all_states_.publish(all);
  for (const std::string& object : world_.objectNames())
    frames.transforms.push_back(toTransform(world_.objectPose(object), "world", object, now));
  if (!frames.transforms.empty())
    tf_.publish(frames);
  contacts_.publish(toMsg(world_.contacts(), now));
}

void PhysicsNode::atStamp(const ros::Time& stamp, std::function<void()> apply)
{
  if (stamp.isZero() || stamp.toSec() <= world_.time())
    return apply();
  if (due_.size() >= kMaxPendingInput)
    throw InputError("more than " + std::to_string(kMaxPendingInput) + " stamped inputs wait for their time");
  due_.emplace(stamp.toSec(), std::move(apply));
}

void PhysicsNode::applyDueInput()
{
  while (!due_.empty() && due_.begin()->first <= world_.time())
  {
    const auto apply = std::move(due_.begin()->second);
    due_.erase(due_.begin());
    apply();
  }
}

void PhysicsNode::onHand(const HandConstPtr& m)
{
  guarded("hand", [&] {
    const Eigen::Isometry3d pose = toEigen(m->pose);
    atStamp(m->header.stamp, [this, m, pose] {
      guarded("hand", [&] { world_.operatorInput().setHand(m->id, pose, m->radius); });
    });
    acknowledge("hand " + m->id, m->header.stamp);
  });
}

void PhysicsNode::onSpringTarget(const SpringTargetConstPtr& m)
{
  guarded("spring_target", [&] {
    const Eigen::Isometry3d target = toEigen(m->target);
    atStamp(m->header.stamp, [this, m, target] {
      guarded("spring_target", [&] { world_.operatorInput().moveSpring(m->id, target, toEigen(m->velocity)); });
    });
    acknowledge("spring_target " + m->id, m->header.stamp);
  });
}

void PhysicsNode::acknowledge(const std::string& what, const ros::Time& stamp)
{
  std_msgs::Header queued;
  queued.stamp = stamp;
  queued.frame_id = what;
  input_queued_.publish(queued);
}
}  // namespace vrrw_physics
