// The persistent service calls and the workspace check against a real master (rostest).
#include <actionlib_msgs/GoalStatusArray.h>
#include <atomic>
#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>

using vrrw_common::PersistentServices;
using vrrw_common::ServiceError;
using vrrw_common::WorkspaceError;

namespace
{
using TriggerEvent = ros::ServiceEvent<std_srvs::Trigger::Request, std_srvs::Trigger::Response>;

/// A Trigger server on a spinner of its own, counting calls and the persistent ones among them.
class Server
{
public:
  explicit Server(const std::string& name, double answer_after = 0.0) : spinner_(1, &queue_)
  {
    ros::NodeHandle node;
    node.setCallbackQueue(&queue_);
    server_ = node.advertiseService<TriggerEvent>(
        name, [this, answer_after](TriggerEvent& event) {
          ++calls;
          const auto header = event.getConnectionHeader();
          persistent += header.count("persistent") && header.at("persistent") == "1";
          ros::WallDuration(answer_after).sleep();
          event.getResponse().success = true;
          event.getResponse().message = std::to_string(calls.load());
          return true;
        });
    spinner_.start();
  }
  ~Server() { server_.shutdown(); }
  std::atomic<int> calls{ 0 };
  std::atomic<int> persistent{ 0 };

private:
  ros::CallbackQueue queue_;
  ros::AsyncSpinner spinner_;
  ros::ServiceServer server_;
};

std::string errorOf(PersistentServices& services, const std::string& name)
{
  std_srvs::Trigger srv;
  try
  {
    services.call(name, srv);
  }
  catch (const ServiceError& e)
  {
    return e.what();
  }
  return "no error";
}

std::string workspaceError(const vrrw_common::WorkspaceNeeds& needs)
{
  try
  {
    vrrw_common::checkWorkspace(needs);
  }
  catch (const WorkspaceError& e)
  {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(PersistentServices, EveryCallGoesOverAPersistentLink)
{
  Server server("/counted");
  PersistentServices services;
  for (int i = 1; i <= 200; ++i)
  {
    std_srvs::Trigger srv;
    services.call("/counted", srv);
    ASSERT_EQ(srv.response.message, std::to_string(i));
  }
  EXPECT_EQ(server.calls, 200);
  EXPECT_EQ(server.persistent, 200);
}

TEST(PersistentServices, AMissingServiceIsNamedAfterTheWait)
{
  PersistentServices services({ 0.5, 5.0 });
  EXPECT_EQ(errorOf(services, "/nothing"), "/nothing: no such service after 0.5 s (is the workspace up? ./vrrw up SCENE)");
}

TEST(PersistentServices, ACallIsBoundedAndTheLinkReopensAfterwards)
{
  PersistentServices services({ 5.0, 0.5 });
  {
    Server slow("/slow", 3.0);
    EXPECT_EQ(errorOf(services, "/slow"), "/slow: no answer within 0.5 s");
    EXPECT_EQ(slow.calls, 1);
  }
  Server quick("/slow");
  EXPECT_EQ(errorOf(services, "/slow"), "no error");
  EXPECT_EQ(quick.calls, 1);
}

TEST(PersistentServices, AServerThatRestartedIsCalledAgain)
{
  PersistentServices services({ 0.5, 5.0 });
  auto server = std::make_unique<Server>("/restarting");
  ASSERT_EQ(errorOf(services, "/restarting"), "no error");
  server.reset();
  const std::string gone = errorOf(services, "/restarting");
  EXPECT_TRUE(gone == "/restarting: no such service after 0.5 s (is the workspace up? ./vrrw up SCENE)" ||
              gone == "/restarting: the call failed (the server refused it or went away)")
      << gone;
  server = std::make_unique<Server>("/restarting");
  EXPECT_EQ(errorOf(services, "/restarting"), "no error");
  EXPECT_EQ(server->calls, 1);
}

TEST(WorkspaceCheck, NamesWhatIsMissing)
{
  ros::param::del("/scene");
  EXPECT_EQ(workspaceError({}), "no error");
  EXPECT_EQ(workspaceError({ "ur5e", {}, {} }),
            "no workspace at " + ros::master::getURI() +
                ": a master runs but no scene is up (/scene/robots): start one with ./vrrw up SCENE");
  ros::param::set("/scene/robots/ur5e/arm_joints", std::vector<std::string>{ "ur5e_shoulder_pan_joint" });
  ros::param::set("/scene/robots/left/arm_joints", std::vector<std::string>{ "left_shoulder_pan_joint" });
  EXPECT_EQ(workspaceError({ "ur7", {}, {} }), "robot 'ur7' is not in the running workspace (its robots: left, ur5e)");
  const std::string action = "/ur5e/arm_controller/follow_joint_trajectory";
  EXPECT_EQ(workspaceError({ "ur5e", { action }, {} }),
            "no controller at " + action + " in the running workspace (is it up with --mode fake or physics?)");
  EXPECT_EQ(workspaceError({ "ur5e", {}, { "/ur5e/plan" } }), "no service /ur5e/plan in the running workspace");

  ros::NodeHandle node;
  const auto status = node.advertise<actionlib_msgs::GoalStatusArray>(action + "/status", 1);
  Server plan("/ur5e/plan");
  EXPECT_EQ(workspaceError({ "ur5e", { action }, { "/ur5e/plan" } }), "no error");
}

TEST(WorkspaceCheck, TheShellCommandsCheckTheSame)
{
  ros::param::set("/scene/robots/ur5e/arm_joints", std::vector<std::string>{ "ur5e_shoulder_pan_joint" });
  const std::string tool = VRRW_WORKSPACE_CHECK;
  EXPECT_EQ(std::system((tool + " --robot ur5e").c_str()), 0);
  EXPECT_EQ(WEXITSTATUS(std::system((tool + " --robot ur9 2>/dev/null").c_str())), 1);
  EXPECT_EQ(WEXITSTATUS(std::system((tool + " --robot 2>/dev/null").c_str())), 2);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_ros_helpers");
  ros::NodeHandle node;
  return RUN_ALL_TESTS();
}
