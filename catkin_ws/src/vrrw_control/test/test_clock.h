#pragma once
// A simulated clock the test owns, for controller_node in fake mode on /use_sim_time: the test publishes /clock
// and advances it one tick at a time, each tick only once every controller has run its cycle for it, so
// every control cycle happens (none lost to a loaded machine) and the test acts at simulated instants.
#include "ros_test_helpers.h"

#include <actionlib/client/simple_client_goal_state.h>
#include <atomic>
#include <dirent.h>
#include <functional>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <rosgraph_msgs/Clock.h>
#include <sys/socket.h>

namespace vrrw_control_test
{
/// Turns Nagle's algorithm off on every TCP socket of this process. roscpp sets TCP_NODELAY on a publisher's side
/// only when the subscriber asks (TransportHints().tcpNoDelay()), and the /clock subscription roscpp makes itself
/// for /use_sim_time never asks: each tick then waited in the kernel for the ACK of the one before (fake_mode's
/// interpolant case took 85.9 s instead of 47.0 s).
inline void noDelayOnEverySocket()
{
  DIR* fds = opendir("/proc/self/fd");
  if (!fds)
    return;
  while (const dirent* entry = readdir(fds))
  {
    const int fd = atoi(entry->d_name);
    int type = 0, on = 1;
    socklen_t length = sizeof type;
    sockaddr_storage address{};
    socklen_t address_length = sizeof address;
    if (fd > 2 && getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) == 0 && type == SOCK_STREAM &&
        getsockname(fd, reinterpret_cast<sockaddr*>(&address), &address_length) == 0 &&
        (address.ss_family == AF_INET || address.ss_family == AF_INET6))
      setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
  }
  closedir(fds);
}

class TestClock
{
public:
  /// Publishes `start` (latched: a controller starts at the first tick it sees) and holds it.
  /// Every subscriber's connection gets TCP_NODELAY as it comes (noDelayOnEverySocket).
  TestClock(ros::NodeHandle& nh, const ros::Time& start, double tick = 0.001)
    : pub_(nh.advertise<rosgraph_msgs::Clock>("/clock", 1, [](const ros::SingleSubscriberPublisher&) {
        noDelayOnEverySocket();
      }, ros::SubscriberStatusCallback(), ros::VoidConstPtr(), true))
    , now_(start)
    , tick_(tick)
  {
    publish();
  }

  /// A controller to wait for at every tick: its joint_states `log` and its control period in seconds. First waits
  /// (advancing the clock, at most 30 s of wall time) for its first message: a state published before the test's
  /// subscription was connected is lost, and with the clock held the controller would publish no other.
  void follow(const JointStateLog& log, double period)
  {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0); log.newest().isZero();)
    {
      if (ros::WallTime::now() > end || !ros::ok())
      {
        ADD_FAILURE() << "no joint_states from a controller to follow";
        failed_ = true;
        return;
      }
      advance(tick_);
      ros::WallDuration(0.01).sleep();
    }
    followers_.push_back({ &log, ros::Duration(period) });
  }

  /// The simulated time published last.
  ros::Time now() const { return now_; }

  /// Advances `seconds` of simulated time, tick by tick.
  bool advance(double seconds)
  {
    return advanceUntil([] { return false; }, seconds) || !failed_;
  }

  /// Advances until `done` holds (checked every `check_every` s of simulated time) or `at_most` s have passed;
  /// true once `done`.
  bool advanceUntil(const std::function<bool()>& done, double at_most, double check_every = 0.001)
  {
    const ros::Time end = now_ + ros::Duration(at_most);
    ros::Time check = now_;
    while (now_ < end && !failed_)
    {
      if (now_ >= check)
      {
        if (done())
          return true;
        check = now_ + ros::Duration(check_every);
      }
      now_ += ros::Duration(tick_);
      publish();
      waitForControllers();
    }
    return done();
  }

  /// Advances until the goal of a simple action client has ended (`at_most` s of simulated time at most).
  template <class Client>
  bool advanceUntilDone(const Client& client, double at_most)
  {
    return advanceUntil([&] { return client.getState().isDone(); }, at_most);
  }

private:
  struct Follower
  {
    const JointStateLog* log;
    ros::Duration period;
  };

  void publish()
  {
    rosgraph_msgs::Clock msg;
    msg.clock = now_;
    pub_.publish(msg);
  }

  /// Every controller has cycled within its period of now. Waits on the wall clock (simulated time stands
  /// still meanwhile); 10 s only guards against a controller that died.
  void waitForControllers()
  {
    for (const Follower& f : followers_)
      if (!f.log->waitNewer(now_ - f.period, 10.0))
      {
        ADD_FAILURE() << "no joint_states within " << f.period << " s of " << now_ << " (latest " << f.log->newest()
                      << ")";
        failed_ = true;
        return;
      }
  }

  ros::Publisher pub_;
  ros::Time now_;
  double tick_;
  std::vector<Follower> followers_;
  bool failed_ = false;
};

/// Waits (wall clock, at most `seconds`) until the client is connected, advancing `clock` meanwhile: an action
/// server publishes the status a client waits for on a timer of simulated time.
template <class Client>
bool waitForServer(TestClock& clock, Client& client, double seconds = 30.0)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!client.isServerConnected())
  {
    if (ros::WallTime::now() > end || !ros::ok())
      return false;
    clock.advance(0.01);
    ros::WallDuration(0.01).sleep();
  }
  return true;
}

/// Waits (wall clock, bounded) until the server has taken the goal: accepted or refused while the clock stands.
template <class Client>
bool waitTaken(Client& client, double seconds = 10.0)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::WallTime::now() < end)
  {
    if (client.getState() != actionlib::SimpleClientGoalState::PENDING)
      return true;
    ros::WallDuration(0.001).sleep();
  }
  return false;
}
}  // namespace vrrw_control_test
