#pragma once
// physics_node's ROS layer: a PhysicsWorld, the robots' controllers loaded into it, stepped in one thread
// at a real-time factor, with its topics and services.
#include <vrrw_physics/Hand.h>
#include <vrrw_physics/SpringTarget.h>
#include <vrrw_physics/joint_frames.h>
#include <vrrw_physics/Step.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/realtime_pacer.h>
#include <vrrw_physics/report_throttle.h>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "loaded_controllers.h"

namespace vrrw_physics
{
/// \brief How physics_node runs its world.
struct NodeOptions
{
  double rtf = 1.0;            ///< real-time factor; infinity: as fast as the cores allow
  double publish_rate = 50.0;  ///< Hz of simulated time: joint_states, object tf and contacts (a viewer's rate)
  double clock_rate = 100.0;   ///< Hz of simulated time of /clock (and whenever the simulation stops); 0: each step
  bool paused = false;         ///< start paused (a client steps it)
  bool robot_tf = true;        ///< send the robots' moving frames on /tf with every state (robot_state_publisher
                               ///< then only sends /tf_static)
  std::string controller;      ///< pluginlib class of every robot's controller; empty: none
};

/// \brief The world stepped in the calling thread of run(): before each step every loaded controller reads,
/// updates and writes (lockstep by construction); between steps the global callback queue runs (services,
/// operator input, the controllers' goals). /physics/step is served from a thread of its own that hands the
/// request to the stepping thread and waits for it. Observers get states at publish_rate of simulated time,
/// and the exact state whenever the simulation stops (a pause, the end of a step request).
class PhysicsNode
{
public:
  PhysicsNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const vrrw_scene::Scene& scene,
              const WorldOptions& world_options, const NodeOptions& options);
  ~PhysicsNode();
  void run();

private:
  /// A /physics/step request as the stepping thread carries it out. PROTECTED BY step_mutex_.
  struct StepRequest
  {
    std::uint64_t steps = 0, done = 0;
    bool until_idle = false;
    double rtf = 0.0;     ///< this request's real-time factor; 0: the node's
    bool finished = false;
    bool idle = false;    ///< at the end
    double time = 0.0;    ///< simulated, at the end
    std::string refused;  ///< why it did not run (the world stopped)
  };

  void advance();
  void applyDueInput();
  void stopped();
  bool serveStep(Step::Request& req, Step::Response& res);
  /// The stepping thread's part of a step request, after a step (`stepped`) or before the first; true when it
  /// ended (the state where it stopped is published).
  bool runStepRequest(bool stepped);
  void publishStates();
  void publishClock();
  /// Runs `apply` at simulated `stamp` (zero or past: before the next step), in stamp order.
  void atStamp(const ros::Time& stamp, std::function<void()> apply);
  void onHand(const HandConstPtr& m);
  void onSpringTarget(const SpringTargetConstPtr& m);

  // services (physics_services.cpp)
  void advertiseServices(ros::NodeHandle& pnh);
  void report(const std::string& source, const std::string& message, bool always = false);
  std::string guarded(const std::string& source, const std::function<void()>& call);
  template <class Srv, class Call>
  void service(ros::NodeHandle& pnh, const std::string& name, Call call);

  PhysicsWorld world_;
  NodeOptions options_;
  int publish_every_, clock_every_;
  std::atomic<bool> paused_;  ///< written by the pause services, read by serveStep's thread too
  RealtimePacer pacer_;
  ReportThrottle throttle_;
  LoadedControllers controllers_;
  std::multimap<double, std::function<void()>> due_;
  std::uint64_t states_at_ = ~0ull, clock_at_ = ~0ull;  ///< step counts last published (once per step)  ///< stamped operator input by simulated time
  std::vector<ros::Publisher> robot_states_;
  std::vector<JointFrames> robot_frames_;  ///< per robot, beside robot_states_; empty without robot_tf
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher all_states_, contacts_, errors_, clock_, tf_;
  /// ~input_queued (std_msgs/Header): each hand or spring target once it is queued here, frame_id "hand <id>"
  /// or "spring_target <id>", stamp its own: a lockstep client that waits for it before stepping past the stamp
  /// knows physics applies it there (a message seen on the input topic itself may still be on its way here).
  ros::Publisher input_queued_;
  void acknowledge(const std::string& what, const ros::Time& stamp);
  std::vector<ros::ServiceServer> services_;

  std::mutex step_mutex_;
  std::condition_variable step_done_;
  std::unique_ptr<StepRequest> step_;  ///< PROTECTED BY step_mutex_; set by serveStep, run by the stepping thread
  ros::CallbackQueue step_queue_;      ///< /physics/step alone, served by step_thread_
  ros::ServiceServer step_service_;
  std::thread step_thread_;
};
}  // namespace vrrw_physics
