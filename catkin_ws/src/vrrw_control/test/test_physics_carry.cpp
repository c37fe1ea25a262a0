// Node test (rostest, real master): issue 22's carry. Physics mode, the controller inside vrrw_physics'
// physics_node (lockstep; the test steps simulated time). The UR5e of pick_place_drill takes the 1.5 kg drill
// from above as the ghost does (vrrw_kinematics' top grasp and planner, the default time-optimal profile),
// closes the gripper with GripperCommand's default max_effort 0, lifts the drill and carries it 25 cm: every
// goal ends within the controller's goal tolerance (0.01 rad), and the arm ends as close to the carry's goal
// as when the gripper closed on nothing. On main before issue 22 this carry ended 7.9 mrad off (the issue's
// run at rtf 1 aborted: wrist_1 0.0117 rad off, beyond the 0.01 rad goal tolerance).
#include <vrrw_common/ros/action_client.h>

#include <cmath>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_kinematics/top_grasp.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_scene/scene_loader.h>
#include <vrrw_trajectory/msg_conversions.h>

#include "lockstep_client.h"

using namespace vrrw_control_test;
using ArmClient = vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = vrrw_common::ActionClient<control_msgs::GripperCommandAction>;

namespace
{
/// What a carry ended with: the controller's answer to the last goal and the arm's distance from its end.
struct Carried
{
  int error_code = 0;
  std::string error_string;
  double error = 0.0;  ///< rad, largest |q - goal| of the six arm joints where the simulation stopped
  std::string joint;   ///< the joint of that error
  Eigen::Vector3d drill_moved = Eigen::Vector3d::Zero();  ///< m, where the carry took the drill (tf)
};

/// The planning side of the cell: the scene's collision world with the drill where the scene has it.
class Cell
{
public:
  Cell()
    : scene_(vrrw_scene::loadScene("pick_place_drill"))
    , world_(vrrw_kinematics::CollisionWorld::fromScene(scene_))
    , state_(vrrw_kinematics::initialState(world_.model(), scene_))
    , arm_(world_, *scene_.robot("ur5e"))
  {
    world_.loadOrComputeAllowedCollisions(scene_.cache_dir);
  }
  const vrrw_scene::Scene& scene() const { return scene_; }
  /// The TCP over the drill's housing, fingers across it (vrrw_evaluation's grasp), `above` m higher and
  /// `toward_front` m along -y (toward the robot's front).
  Eigen::Isometry3d overDrill(double above, double toward_front = 0.0) const
  {
    Eigen::Isometry3d tcp = vrrw_kinematics::topGrasp(scene_.object("drill")->pose, Eigen::Vector3d(0.03, 0.0, 0.203));
    tcp.translation() += Eigen::Vector3d(0.0, -toward_front, above);
    return tcp;
  }
  /// A plan from `q` to the TCP pose `tcp`, timed as the ghost times it (time-optimal at full speed).
  control_msgs::FollowJointTrajectoryGoal plan(const std::vector<double>& q, const Eigen::Isometry3d& tcp)
  {
    vrrw_kinematics::TrajectoryRequest request;
    request.plan.start = Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size()));
    request.plan.goal_pose = tcp;
    request.plan.time_limit = 5.0;
    const vrrw_kinematics::TrajectoryResult result = arm_.planTrajectory(request, state_);
    EXPECT_TRUE(result.success) << result.message;
    control_msgs::FollowJointTrajectoryGoal goal;
    if (result.success)
      goal.trajectory = vrrw_trajectory::toMsg(result.trajectory);
    return goal;
  }
  /// The drill fixed to the TCP with the arm at `q` (it may touch the gripper's links), as the ghost holds it.
  void attachDrill(const std::vector<double>& q)
  {
    state_ = arm_.withJointValues(state_, Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size())));
    std::vector<std::string> gripper_links;
    for (std::vector<int> below{ world_.model().linkIndex("ur5e_tool0") }; !below.empty();)
    {
      const auto& link = world_.model().links()[std::size_t(below.back())];
      below.pop_back();
      gripper_links.push_back(link.name);
      below.insert(below.end(), link.child_links.begin(), link.child_links.end());
    }
    world_.attachObject("drill", "ur5e_tcp", state_, gripper_links);
  }
  void detachDrill() { world_.detachObject("drill", state_); }

private:
  vrrw_scene::Scene scene_;
  vrrw_kinematics::CollisionWorld world_;
  Eigen::VectorXd state_;
  vrrw_kinematics::Arm arm_;
};

class Carry
{
public:
  explicit Carry(ros::NodeHandle& nh)
    : arm_("/ur5e/arm_controller/follow_joint_trajectory")
    , gripper_("/ur5e/gripper_controller/gripper_cmd")
    , states_(nh, "/ur5e/joint_states")
  {
  }
  bool ready()
  {
    return sim_.waitForPhysics() && arm_.waitForServer(ros::Duration(30.0)) &&
           gripper_.waitForServer(ros::Duration(30.0));
  }
  /// The drill on its spot (`present`) or 2 m away on the floor, left to settle.
  void placeDrill(bool present)
  {
    vrrw_physics::SetObjectPose put;
    put.request.object = "drill";
    Eigen::Isometry3d pose = cell_.scene().object("drill")->pose;
    if (!present)
      pose.translation() = Eigen::Vector3d(2.0, 2.0, 0.1);
    put.request.pose.position.x = pose.translation().x();
    put.request.pose.position.y = pose.translation().y();
    put.request.pose.position.z = pose.translation().z();
    const Eigen::Quaterniond r(pose.rotation());
    put.request.pose.orientation.w = r.w(), put.request.pose.orientation.x = r.x();
    put.request.pose.orientation.y = r.y(), put.request.pose.orientation.z = r.z();
    vrrw_common::services().call("/physics/set_object_pose", put);
    EXPECT_TRUE(put.response.success) << put.response.message;
    sim_.step(0.5);
  }
  /// Over the drill's spot, down, the gripper closed (max_effort 0: the default), lifted 12 cm and carried
  /// 25 cm toward the robot's front; whether the drill is there or not.
  Carried run()
  {
    EXPECT_EQ(move(cell_.overDrill(0.12)).error_code, 0);
    EXPECT_EQ(move(cell_.overDrill(0.0)).error_code, 0);
    control_msgs::GripperCommandGoal close;
    close.command.position = 0.8;  // past the housing: the grip stalls on it
    gripper_.sendGoal(close);
    EXPECT_TRUE(waitAccepted(gripper_));
    sim_.step(3.0, true);
    sim_.step(0.5);  // the squeeze settles
    cell_.attachDrill(arm());
    EXPECT_EQ(move(cell_.overDrill(0.12)).error_code, 0);
    Carried carried = move(cell_.overDrill(0.12, 0.25));
    carried.drill_moved = drill() - cell_.scene().object("drill")->pose.translation();
    cell_.detachDrill();
    gripper_.sendGoal(control_msgs::GripperCommandGoal());  // open
    EXPECT_TRUE(waitAccepted(gripper_));
    sim_.step(3.0, true);
    return carried;
  }

private:
  /// Where physics has the drill now (its tf frame, published at every stop).
  Eigen::Vector3d drill()
  {
    const ros::Time now = sim_.now();
    // (wall clock: a timeout in simulated time never ends while the simulation waits)
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(5.0);
         !tf_.canTransform("world", "drill", now) && ros::WallTime::now() < end;)
      ros::WallDuration(0.002).sleep();
    if (!tf_.canTransform("world", "drill", now))
    {
      ADD_FAILURE() << "no tf of the drill at " << now << " (the newest: "
                    << tf_.lookupTransform("world", "drill", ros::Time(0)).header.stamp << ")";
      return Eigen::Vector3d::Constant(std::nan(""));
    }
    return tf2::transformToEigen(tf_.lookupTransform("world", "drill", now)).translation();
  }
  /// The arm joints' positions in the state where the simulation waits.
  std::vector<double> arm()
  {
    sensor_msgs::JointState s;
    EXPECT_TRUE(states_.waitFor(sim_.now(), s));
    return armOf(s);
  }
  std::vector<double> armOf(const sensor_msgs::JointState& s) const
  {
    std::vector<double> q;
    for (const std::string& joint : armJoints("ur5e_"))
      for (std::size_t i = 0; i < s.name.size(); ++i)
        if (s.name[i] == joint)
          q.push_back(s.position[i]);
    EXPECT_EQ(q.size(), 6u);
    return q;
  }
  Carried move(const Eigen::Isometry3d& tcp)
  {
    control_msgs::FollowJointTrajectoryGoal goal = cell_.plan(arm(), tcp);
    Carried out;
    if (goal.trajectory.points.empty())
      return out.error_code = -1, out.error_string = "no plan", out;
    goal.trajectory.header.stamp = sim_.now();
    arm_.sendGoal(goal);
    EXPECT_TRUE(waitAccepted(arm_));
    const ros::Time stopped = sim_.step(30.0, true);
    EXPECT_TRUE(arm_.waitForResult(ros::Duration(10.0)));  // on its way (wall clock)
    out.error_code = arm_.getResult()->error_code;
    out.error_string = arm_.getResult()->error_string;
    sensor_msgs::JointState s;
    EXPECT_TRUE(states_.waitFor(stopped, s));
    const std::vector<double> q = armOf(s), &end = goal.trajectory.points.back().positions;
    for (std::size_t j = 0; j < q.size(); ++j)
      if (const double e = std::abs(q[j] - end[j]); e > out.error)
        out.error = e, out.joint = goal.trajectory.joint_names[j];
    return out;
  }

  Lockstep sim_;
  Cell cell_;
  ArmClient arm_;
  GripperClient gripper_;
  JointStateLog states_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_{ tf_ };
};
}  // namespace

TEST(PhysicsCarry, AHeldDrillEndsTheCarryWithinTheGoalTolerance)
{
  ros::NodeHandle nh;
  Carry carry(nh);
  ASSERT_TRUE(carry.ready());
  carry.placeDrill(false);
  const Carried empty = carry.run();
  carry.placeDrill(true);
  const Carried held = carry.run();
  std::cout << "carry: final error " << held.error << " rad (" << held.joint << ") holding the drill, " << empty.error
            << " rad (" << empty.joint << ") with the gripper closed on nothing; result " << held.error_code << " "
            << held.error_string << "; drill moved " << held.drill_moved.transpose() << " m" << std::endl;
  EXPECT_NEAR(held.drill_moved.z(), 0.12, 0.02) << "the drill was not carried";
  EXPECT_NEAR(held.drill_moved.y(), -0.25, 0.02) << "the drill was not carried";
  EXPECT_EQ(held.error_code, 0) << held.error_string;
  EXPECT_EQ(empty.error_code, 0) << empty.error_string;
  // measured 3.7e-3 (wrist_2) holding it, 1.8e-4 closed on nothing; on main before issue 22 (max_effort 0 squeezed
  // with the finger drive's own 625 N per pad, the drives solved before the contacts) 7.9e-3 holding it
  EXPECT_LT(held.error, 6e-3);
  EXPECT_LT(empty.error, 5e-4);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_carry");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
