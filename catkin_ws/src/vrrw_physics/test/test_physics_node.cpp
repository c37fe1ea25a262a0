// Node test against a real master, without controllers: joint states per robot and combined, objects on tf,
// contacts, bad input gets a rate-limited error on ~errors and the node keeps running, hands, stamped input
// taking effect at its stamp, pause / unpause / step / reset, /clock.
#include <vrrw_physics/Contacts.h>
#include <vrrw_physics/Hand.h>
#include <vrrw_physics/SetGains.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_physics/SetSpring.h>
#include <vrrw_physics/SpringTarget.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/ros/persistent_service.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <vrrw_physics/Step.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace
{
struct Listener
{
  sensor_msgs::JointState last;
  int count = 0;
  ros::Time newest;  ///< the latest stamp of any /ur5e/joint_states received
  std::vector<std::string> errors;

  Listener()
  {
    ros::NodeHandle nh;
    states = nh.subscribe<sensor_msgs::JointState>("/ur5e/joint_states", 10, [this](const sensor_msgs::JointStateConstPtr& m) {
      last = *m;
      ++count;
      newest = std::max(newest, m->header.stamp);
    });
    all = nh.subscribe<sensor_msgs::JointState>("/joint_states", 10, [this](const sensor_msgs::JointStateConstPtr& m) { all_last = *m; });
    error_sub = nh.subscribe<std_msgs::String>("/physics/errors", 10, [this](const std_msgs::StringConstPtr& m) { errors.push_back(m->data); });
  }

  bool waitFor(const std::function<bool()>& done, double seconds)
  {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::WallTime::now() < end && ros::ok())
    {
      ros::spinOnce();
      if (done())
        return true;
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  double position(const std::string& joint) const
  {
    const auto q = vrrw_common::findValues(last.name, last.position, { joint });
    return q ? q->front() : std::numeric_limits<double>::quiet_NaN();
  }

  int errorsMentioning(const std::string& text) const
  {
    return int(std::count_if(errors.begin(), errors.end(),
                             [&](const std::string& e) { return e.find(text) != std::string::npos; }));
  }

  bool errorMentions(const std::string& text) const
  {
    return errorsMentioning(text) > 0;
  }

  sensor_msgs::JointState all_last;
  ros::Subscriber states, all, error_sub;
};

bool trigger(const std::string& service)
{
  std_srvs::Trigger srv;
  return vrrw_common::services().tryCall(service, srv) && srv.response.success;
}

bool empty(const std::string& service)
{
  std_srvs::Empty srv;
  return vrrw_common::services().tryCall(service, srv);
}

/// /physics/step over one persistent connection.
vrrw_physics::Step::Response step(double duration, bool until_idle = false)
{
  vrrw_physics::Step srv;
  srv.request.duration = duration;
  srv.request.until_idle = until_idle;
  EXPECT_TRUE(vrrw_common::services().tryCall("/physics/step", srv));
  return srv.response;
}
}  // namespace

TEST(PhysicsNode, PublishesJointStatesAndObjectFrames)
{
  Listener l;
  ASSERT_TRUE(ros::service::waitForService("/physics/reset", ros::Duration(30)));
  ASSERT_TRUE(l.waitFor([&] { return l.count > 0 && !l.all_last.name.empty(); }, 10.0));
  EXPECT_EQ(l.last.name.size(), 12u);
  EXPECT_EQ(l.last.name.front(), "ur5e_shoulder_pan_joint");
  EXPECT_EQ(l.last.position.size(), l.last.name.size());
  EXPECT_EQ(l.last.velocity.size(), l.last.name.size());
  EXPECT_EQ(l.all_last.name.size(), 12u);
  EXPECT_NEAR(l.position("ur5e_shoulder_lift_joint"), -1.5708, 1e-3);
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener tf(buffer);
  EXPECT_TRUE(buffer.canTransform("world", "drill", ros::Time(0), ros::Duration(5.0)));
  // the robots' moving frames come with the states (robot_state_publisher sends /tf_static alone)
  EXPECT_TRUE(buffer.canTransform("ur5e_upper_arm_link", "ur5e_forearm_link", ros::Time(0), ros::Duration(5.0)));
  EXPECT_TRUE(buffer.canTransform("ur5e_right_outer_knuckle", "ur5e_right_inner_finger", ros::Time(0)));  // mimic
}

TEST(PhysicsNode, BadInputIsReportedAndTheNodeKeepsRunning)
{
  Listener l;
  ros::NodeHandle nh;
  ros::Publisher hands = nh.advertise<vrrw_physics::Hand>("/physics/hand", 10);
  ASSERT_TRUE(l.waitFor([&] { return hands.getNumSubscribers() > 0 && l.count > 0; }, 10.0));
  vrrw_physics::Hand bad;
  bad.id = "nan";
  bad.radius = 0.05;
  bad.pose.position.x = std::numeric_limits<double>::quiet_NaN();
  bad.pose.orientation.w = 1.0;
  hands.publish(bad);
  bad.id = "zero";
  bad.pose.position.x = 0.0;
  bad.pose.orientation.w = 0.0;
  hands.publish(bad);
  EXPECT_TRUE(l.waitFor([&] { return l.errorMentions("hand 'nan'") && l.errorMentions("quaternion is zero"); }, 5.0))
      << (l.errors.empty() ? "no errors" : l.errors.back());

  vrrw_physics::SetGains gains;
  gains.request.robot = "ur5e";
  gains.request.stiffness = { 1.0, 2.0 };
  gains.request.damping = { 1.0, 2.0 };
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_gains", gains));
  EXPECT_FALSE(gains.response.success);
  EXPECT_NE(gains.response.message.find("6 joint names but 2"), std::string::npos) << gains.response.message;
  gains.request.joints = { "ur5e_elbow_joint" };
  gains.request.stiffness = { -5.0 };
  gains.request.damping = { 1.0 };
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_gains", gains));
  EXPECT_FALSE(gains.response.success);

  vrrw_physics::SetSpring spring;
  spring.request.id = "hand";
  spring.request.body = "ur5e_no_such_link";
  spring.request.target.orientation.w = 1.0;
  spring.request.stiffness = 100.0;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_spring", spring));
  EXPECT_FALSE(spring.response.success);
  EXPECT_NE(spring.response.message.find("ur5e_no_such_link"), std::string::npos);

  const int before = l.count;
  EXPECT_TRUE(l.waitFor([&] { return l.count > before + 5; }, 5.0));
  EXPECT_NEAR(l.position("ur5e_elbow_joint"), 1.5708, 1e-3);  // the rejected targets were not applied
}

TEST(PhysicsNode, PauseUnpauseAndStep)
{
  Listener l;
  ASSERT_TRUE(l.waitFor([&] { return l.count > 0; }, 10.0));
  const auto running = step(0.1);
  EXPECT_FALSE(running.success);
  EXPECT_EQ(running.message, "the simulation runs: pause it first (/physics/pause)");
  ASSERT_TRUE(empty("/physics/pause"));
  ASSERT_TRUE(empty("/physics/pause"));  // twice: answered, still paused
  const auto at = step(0.0);
  ASSERT_TRUE(at.success) << at.message;
  EXPECT_EQ(at.steps, 0u);
  // nothing moved while paused: whatever arrives now (however late) is stamped at or before the pause
  l.waitFor([] { return false; }, 0.6);
  const int paused_at = l.count;
  EXPECT_LE(l.newest, at.time);
  EXPECT_EQ(step(0.0).time, at.time);
  const auto stepped = step(0.1);
  ASSERT_TRUE(stepped.success) << stepped.message;
  EXPECT_EQ(stepped.steps, 100u);
  EXPECT_NEAR((stepped.time - at.time).toSec(), 0.1, 1e-6);
  EXPECT_TRUE(stepped.idle);  // no controllers here
  EXPECT_TRUE(l.waitFor([&] { return l.last.header.stamp == stepped.time; }, 2.0));  // the state at the stop
  EXPECT_FALSE(step(-1.0).success);
  EXPECT_EQ(step(1e9).message, "duration: 1000000000.000000 outside [0, 600] s");
  ASSERT_TRUE(empty("/physics/unpause"));
  ASSERT_TRUE(empty("/physics/unpause"));  // without pause: answered, still running
  EXPECT_TRUE(l.waitFor([&] { return l.count > paused_at + 10; }, 20.0));
}

TEST(PhysicsNode, StampedInputTakesEffectAtItsStamp)
{
  Listener l;
  ros::NodeHandle nh;
  ros::Publisher hands = nh.advertise<vrrw_physics::Hand>("/physics/hand", 10);
  ASSERT_TRUE(l.waitFor([&] { return hands.getNumSubscribers() > 0 && l.count > 0; }, 10.0));
  ASSERT_TRUE(empty("/physics/pause"));
  const ros::Time now = step(0.0).time;
  vrrw_physics::Hand hand;
  hand.header.stamp = now + ros::Duration(1.0);  // appears 1 s from now, removed 0.5 s after that
  hand.id = "stamped";
  hand.pose.position.z = 2.0;
  hand.pose.orientation.w = 1.0;
  hand.radius = 0.05;
  hands.publish(hand);
  // it arrives while the simulation waits (nothing tells when a topic message has arrived: a delivery of a few
  // tenths of a second is all this assumes; a hand later than 1.05 s of the step would be removed later)
  l.waitFor([] { return false; }, 1.0);
  ASSERT_TRUE(step(1.45).success);
  l.waitFor([] { return false; }, 0.3);
  EXPECT_FALSE(l.errorMentions("hand 'stamped': no pose for"));
  ASSERT_TRUE(step(0.1).success);
  EXPECT_TRUE(l.waitFor([&] { return l.errorMentions("hand 'stamped': no pose for"); }, 2.0));
  ASSERT_TRUE(empty("/physics/unpause"));
}

TEST(PhysicsNode, CompliantArmFollowsAnOperatorSpring)
{
  Listener l;
  ros::NodeHandle nh;
  ros::Publisher move = nh.advertise<vrrw_physics::SpringTarget>("/physics/spring_target", 10);
  ASSERT_TRUE(l.waitFor([&] { return l.count > 0 && move.getNumSubscribers() > 0; }, 10.0));
  ASSERT_TRUE(trigger("/physics/reset"));
  vrrw_physics::SetMode mode;
  mode.request.robot = "ur5e";
  mode.request.mode = "compliant";
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_mode", mode) && mode.response.success) << mode.response.message;
  vrrw_physics::SetSpring spring;
  spring.request.id = "hand";
  spring.request.body = "ur5e_tool0";
  spring.request.target.position.y = 5.0;  // far along +y: a constant 20 N pull
  spring.request.target.orientation.w = 1.0;
  spring.request.stiffness = 1000.0;
  spring.request.max_force = 20.0;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_spring", spring) && spring.response.success) << spring.response.message;
  const double pan = l.position("ur5e_shoulder_pan_joint");
  EXPECT_TRUE(l.waitFor([&] { return std::abs(l.position("ur5e_shoulder_pan_joint") - pan) > 0.05; }, 20.0));
  vrrw_physics::SpringTarget target;
  target.id = "nobody";
  target.target.orientation.w = 1.0;
  move.publish(target);
  EXPECT_TRUE(l.waitFor([&] { return l.errorMentions("nobody"); }, 5.0));
  spring.request.release = true;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_spring", spring) && spring.response.success);
  mode.request.mode = "rigid";
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_mode", mode) && mode.response.success);
  const int after = l.count;
  ASSERT_TRUE(l.waitFor([&] { return l.count > after + 2; }, 5.0));
  const double held = l.position("ur5e_shoulder_pan_joint");
  l.waitFor([] { return false; }, 1.0);
  EXPECT_NEAR(l.position("ur5e_shoulder_pan_joint"), held, 1e-3);  // rigid holds where the push left it
  ASSERT_TRUE(trigger("/physics/reset"));
}

TEST(PhysicsNode, PublishesContactsAndTakesNamedHands)
{
  Listener l;
  ros::NodeHandle nh;
  vrrw_physics::Contacts contacts;
  int received = 0;
  ros::Subscriber sub =
      nh.subscribe<vrrw_physics::Contacts>("/physics/contacts", 10, [&](const vrrw_physics::ContactsConstPtr& m) {
        contacts = *m;
        ++received;
      });
  ros::Publisher hands = nh.advertise<vrrw_physics::Hand>("/physics/hand", 10);
  ASSERT_TRUE(l.waitFor([&] { return received > 5 && hands.getNumSubscribers() > 0; }, 10.0));
  ASSERT_TRUE(trigger("/physics/reset"));
  const auto drillOnTable = [&] {
    for (const auto& c : contacts.contacts)
      if (c.body_a == "drill" && c.body_b == "table")
        return c.normal_force;
    return 0.0;
  };
  EXPECT_TRUE(l.waitFor([&] { return std::abs(drillOnTable() - 1.5 * 9.81) < 1.5; }, 20.0)) << drillOnTable() << " N";
  vrrw_physics::Hand hand;
  hand.id = "left";
  hand.pose.position.z = 2.0;  // in free space, above everything
  hand.pose.orientation.w = 1.0;
  hand.radius = 1.0;
  hands.publish(hand);
  EXPECT_TRUE(l.waitFor([&] { return l.errorMentions("hand 'left' radius: 1 outside [0, 0.25] m"); }, 5.0));
  hand.radius = 0.05;
  hands.publish(hand);  // accepted; it falls silent and goes after 0.5 s
  EXPECT_TRUE(l.waitFor([&] { return l.errorMentions("hand 'left': no pose for"); }, 20.0));
}

TEST(PhysicsNode, WildInputIsRefusedAndRepeatedErrorsAreRateLimited)
{
  Listener l;
  ros::NodeHandle nh;
  ros::Publisher hands = nh.advertise<vrrw_physics::Hand>("/physics/hand", 1000);
  ASSERT_TRUE(l.waitFor([&] { return hands.getNumSubscribers() > 0 && l.count > 0; }, 10.0));
  vrrw_physics::SetSpring spring;  // the probe that froze the node before: stiffness and max_force 1e12
  spring.request.id = "hand";
  spring.request.body = "ur5e_wrist_3_link";
  spring.request.target.orientation.w = 1.0;
  spring.request.stiffness = 1e12;
  spring.request.max_force = 1e12;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_spring", spring));
  EXPECT_FALSE(spring.response.success);
  EXPECT_NE(spring.response.message.find("stiffness: 1e+12 outside [0, 10000] N/m"), std::string::npos)
      << spring.response.message;
  vrrw_physics::SetObjectPose pose;
  pose.request.object = "drill";
  pose.request.pose.position.x = 1e300;
  pose.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_object_pose", pose));
  EXPECT_FALSE(pose.response.success);
  EXPECT_NE(pose.response.message.find("outside [-100, 100] m"), std::string::npos) << pose.response.message;
  pose.request.object = "table";
  pose.request.pose.position.x = 0.0;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_object_pose", pose));
  EXPECT_NE(pose.response.message.find("fixed"), std::string::npos) << pose.response.message;
  // 300 bad hands in 0.3 s (longer on a loaded machine): one error line, then at most one a second (of wall
  // time: the throttle serves a person reading the errors) that counts the rest.
  vrrw_physics::Hand bad;
  bad.id = "huge";
  bad.pose.orientation.w = 1.0;
  bad.radius = 3.0;
  ros::spinOnce();
  const int before = l.errorsMentioning("hand 'huge' radius");
  const ros::WallTime start = ros::WallTime::now();
  for (int i = 0; i < 300; ++i)
  {
    hands.publish(bad);
    ros::WallDuration(0.001).sleep();
  }
  l.waitFor([] { return false; }, 1.5);
  const double seconds = (ros::WallTime::now() - start).toSec();
  const int lines = l.errorsMentioning("hand 'huge' radius") - before;
  std::cout << "300 bad hands: " << lines << " error lines in " << seconds << " s\n";
  EXPECT_GE(lines, 1);
  EXPECT_LE(lines, 2 + int(seconds));  // the first, then one per second begun
}

TEST(PhysicsNode, PublishesSimulatedTimeOnClock)
{
  Listener l;
  ros::NodeHandle nh;
  std::vector<double> ticks;
  // roscpp can deliver a latched message twice to a subscriber that connects while it is published (the latched
  // copy is queued outside the publication's lock): a repeated time is that, not a tick
  ros::Subscriber clock = nh.subscribe<rosgraph_msgs::Clock>("/clock", 100, [&](const rosgraph_msgs::ClockConstPtr& m) {
    if (ticks.empty() || m->clock.toSec() != ticks.back())
      ticks.push_back(m->clock.toSec());
  });
  ASSERT_TRUE(l.waitFor([&] { return ticks.size() > 20 && l.count > 0; }, 10.0));
  EXPECT_GT(ticks.back(), ticks.front());
  EXPECT_NEAR(ticks[1] - ticks[0], 0.01, 1e-6);  // ~clock_rate 100 Hz of simulated time
  EXPECT_LT(l.last.header.stamp.toSec(), 1e6);     // joint states carry simulated time
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
