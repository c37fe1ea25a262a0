// ./vrrw bench interaction [--samples N] [--hold S]: brings up a physics cell of pick_place_drill on its own
// master (physics, controller, interaction node), then measures (1) marker pose in -> ghost joint_states out
// at 100 Hz input and (2) a hand dragging the free-driven wrist 20 cm at 0.2 m/s, and the drift after release.
// The last line is JSON.
#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <netinet/in.h>
#include <map>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <vrrw_common/options.h>
#include <vrrw_msgs/GhostPreset.h>

#include "hand_drag.h"

namespace
{
int freePort()
{
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  bind(s, reinterpret_cast<sockaddr*>(&address), sizeof(address));
  socklen_t size = sizeof(address);
  getsockname(s, reinterpret_cast<sockaddr*>(&address), &size);
  close(s);
  return ntohs(address.sin_port);
}

bool masterUp(int port)
{
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool up = connect(s, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  close(s);
  return up;
}

double percentile(std::vector<double> v, double p)
{
  if (v.empty())
    return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

/// Marker feedback at 100 Hz along a 5 cm circle about the ghost's square_center TCP; ms to the ghost state.
std::vector<double> markerLatency(ros::NodeHandle& nh, tf2_ros::Buffer& tf, int samples, int& answered)
{
  vrrw_msgs::GhostPreset preset;
  preset.request.name = "square_center";
  vrrw_common::services().tryCall("/ur5e/ghost/preset", preset);
  ros::WallDuration(0.5).sleep();
  const Eigen::Isometry3d tcp = tf2::transformToEigen(tf.lookupTransform("world", "ghost/ur5e_tcp", ros::Time(0), ros::Duration(5.0)));
  std::mutex mutex;
  // sent feedback by its stamp (which the ghost's answer carries), with the wall time it left: latency is wall
  // time, whether this process runs on the simulation's clock or not (it reads /use_sim_time as it starts)
  std::map<ros::Time, ros::WallTime> sent;
  std::vector<double> latencies;
  ros::Subscriber sub = nh.subscribe<sensor_msgs::JointState>(
      "/ur5e/ghost/joint_states", 1000,
      [&](const sensor_msgs::JointStateConstPtr& m) {
        const ros::WallTime now = ros::WallTime::now();
        std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = sent.find(m->header.stamp); it != sent.end())
        {
          latencies.push_back((now - it->second).toSec() * 1e3);
          sent.erase(it);
        }
      },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  ros::Publisher pub = nh.advertise<visualization_msgs::InteractiveMarkerFeedback>("/interaction/feedback", 100);
  for (int i = 0; i < 300 && (pub.getNumSubscribers() == 0 || sub.getNumPublishers() == 0); ++i)
    ros::WallDuration(0.01).sleep();
  visualization_msgs::InteractiveMarkerFeedback f;
  f.header.frame_id = "world";
  f.client_id = "bench";
  f.marker_name = "ur5e";
  f.event_type = visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE;
  ros::WallTime tick = ros::WallTime::now();
  for (int i = 0; i < samples; ++i)
  {
    const double a = 2 * M_PI * i / 200.0;  // one turn in 2 s: 16 cm/s
    Eigen::Isometry3d target = tcp;
    target.translation() += Eigen::Vector3d(0.05 * std::cos(a) - 0.05, 0.05 * std::sin(a), 0.0);
    f.pose = tf2::toMsg(target);
    f.header.stamp = ros::Time::now();
    {
      std::lock_guard<std::mutex> lock(mutex);
      sent[f.header.stamp] = ros::WallTime::now();
    }
    pub.publish(f);
    tick += ros::WallDuration(0.01);
    if (const ros::WallDuration rest = tick - ros::WallTime::now(); rest > ros::WallDuration(0))
      rest.sleep();  // a negative WallDuration would sleep for ever
  }
  ros::WallDuration(0.5).sleep();
  std::lock_guard<std::mutex> lock(mutex);
  answered = static_cast<int>(latencies.size());
  return latencies;
}
}  // namespace

int main(int argc, char** argv)
{
  int samples = 1000;
  double hold = 5.0;
  std::string angular_stiffness = "500", angular_damping = "5";  // the node's defaults
  try
  {
    const vrrw_common::Options options(argc, argv, 1, { "samples", "hold", "angular" });
    options.expectPositional({});
    samples = static_cast<int>(options.count("samples", 1000, 1, 1000000));
    hold = options.number("hold", hold, vrrw_common::Range::closed(0.0, 3600.0, "s"));
    if (options.has("angular"))  // K,D of a grip on a link (0,0: position only, as before issue 13)
    {
      const auto gains = options.list("angular", 2, vrrw_common::Range::closed(0.0, 1e9));
      angular_stiffness = std::to_string(gains[0]), angular_damping = std::to_string(gains[1]);
    }
  }
  catch (const vrrw_common::OptionError& e)
  {
    return std::cerr << "bench interaction: " << e.what() << " (--samples N, --hold S, --angular K,D)\n", 2;
  }
  const int port = freePort();
  const std::string master = "http://127.0.0.1:" + std::to_string(port);
  setenv("ROS_MASTER_URI", master.c_str(), 1);
  const std::string log = "/tmp/vrrw_bench_interaction_" + std::to_string(port) + ".log";
  const pid_t launch = fork();
  if (launch == 0)
  {
    setsid();
    if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr))
      _exit(127);
    const std::string k = "grip_angular_stiffness:=" + angular_stiffness, d = "grip_angular_damping:=" + angular_damping;
    execlp("roslaunch", "roslaunch", "-p", std::to_string(port).c_str(), LAUNCH_FILE, k.c_str(), d.c_str(), (char*)nullptr);
    _exit(127);
  }
  std::cerr << "bench interaction: physics cell of pick_place_drill on " << master << " (log " << log << ")\n";
  int status = 0;
  {
    // the master first: a roscpp node that cannot reach it at start may hang in its retry loop
    for (int i = 0; i < 600 && !masterUp(port); ++i)
      usleep(100000);
    ros::init(argc, argv, "bench_interaction", ros::init_options::NoSigintHandler);
    ros::NodeHandle nh;
    ros::AsyncSpinner spinner(2);
    spinner.start();
    tf2_ros::Buffer tf;
    tf2_ros::TransformListener listener(tf);
    if (!ros::service::waitForService("/ur5e/ghost/preset", ros::Duration(90.0)) ||
        !ros::service::waitForService("/ur5e/free_drive", ros::Duration(10.0)))
    {
      std::cerr << "bench interaction: the cell did not come up (see " << log << ")\n";
      status = 1;
    }
    else
    {
      ros::WallDuration(2.0).sleep();  // controllers take over the physics drives
      int answered = 0;
      const std::vector<double> ms = markerLatency(nh, tf, samples, answered);
      const auto drag = vrrw_interaction_bench::dragWrist(nh, tf, 0.2, 0.2, hold);
      std::cerr << "marker: " << answered << " of " << samples << " poses answered (the rest coalesced)\n"
                << "drag: grabbed " << drag.body << " " << drag.error << "\n";
      std::cout << "{\"scene\": \"pick_place_drill\", \"marker_samples\": " << samples
                << ", \"marker_answered\": " << answered << ", \"marker_median_ms\": " << percentile(ms, 0.5)
                << ", \"marker_p99_ms\": " << percentile(ms, 0.99) << ", \"marker_max_ms\": " << percentile(ms, 1.0)
                << ", \"drag_body\": \"" << drag.body << "\", \"drag_rms_m\": " << drag.rms
                << ", \"drag_max_m\": " << drag.max << ", \"drag_angle_rms_deg\": " << drag.angle_rms
                << ", \"drag_angle_max_deg\": " << drag.angle_max << ", \"grip_angular\": \"" << angular_stiffness << ","
                << angular_damping << "\", \"drift_m\": " << drag.drift << ", \"drift_seconds\": " << hold
                << ", \"drag_error\": \"" << drag.error << "\"}" << std::endl;
      status = drag.error.empty() ? 0 : 1;
    }
    ros::shutdown();
  }
  kill(-launch, SIGINT);
  for (int i = 0; i < 150 && waitpid(launch, nullptr, WNOHANG) == 0; ++i)
    usleep(100000);
  kill(-launch, SIGKILL);
  waitpid(launch, nullptr, 0);
  return status;
}
