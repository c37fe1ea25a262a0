// What a hand grabs (grab_target.h) on the shipped cells: the nearest body, a gripper held by its mount, objects
// only where they move, where an open hand may push.
#include <vrrw_interaction/grab_target.h>
#include <vrrw_interaction/held_objects.h>

#include "library_fixture.h"

using namespace vrrw_interaction;
using vrrw_interaction_test::Cell;

namespace
{
Cell& drillCell()
{
  static Cell cell("pick_place_drill");
  return cell;
}

/// True when no movable joint lies between `link` and its robot's last arm link.
bool rigidWithTheArm(const vrrw_kinematics::RobotModel& model, const std::string& link,
                     const std::vector<std::string>& arm_joints)
{
  for (int l = model.linkIndex(link); model.links()[l].parent_joint >= 0;)
  {
    const vrrw_kinematics::JointModel& joint = model.joints()[model.links()[l].parent_joint];
    if (joint.moves())
      return std::find(arm_joints.begin(), arm_joints.end(), joint.name) != arm_joints.end();
    l = joint.parent_link;
  }
  return true;
}
}  // namespace

TEST(GrabTarget, AHandAtTheTcpHoldsTheGripperByItsMountNotByAFinger)
{
  Cell& cell = drillCell();
  const vrrw_scene::Robot& robot = *cell.scene.robot("ur5e");
  const Eigen::Vector3d tcp = cell.link(robot.tcp_link, cell.state).translation();
  // the nearest body to the TCP is a finger pad (issue 21: a grip on it blew up in physics)
  const auto touched = nearestBody(cell.world, cell.state, tcp, 0.05, [](const auto& b) { return !b.object; });
  ASSERT_TRUE(touched);
  EXPECT_NE(touched->body.find("finger"), std::string::npos) << touched->body;
  GrabRule rule;
  rule.robots = { "ur5e" };
  const auto grabbed = handGrab(cell.world, cell.scene, cell.state, tcp, rule);
  ASSERT_TRUE(grabbed);
  EXPECT_EQ(grabbed->body, "ur5e_robotiq_arg2f_base_link");
  EXPECT_EQ(grabbed->robot, "ur5e");
  EXPECT_LT((grabbed->point_in_world - touched->point_in_world).norm(), 1e-12);  // the same touched point
  EXPECT_LT((cell.link(grabbed->body, cell.state) * grabbed->point_in_body - grabbed->point_in_world).norm(), 1e-12);
  EXPECT_FALSE(handGrab(cell.world, cell.scene, cell.state, tcp, GrabRule{ 0.05, { "ur10e" }, false }));
}

TEST(GrabTarget, EveryLinkIsHeldByABodyRigidWithTheArm)
{
  for (const std::string scene : { "pick_place_drill", "paper_multibot" })
  {
    const Cell cell(scene);
    for (const vrrw_scene::Robot& robot : cell.scene.robots)
      for (const std::string& link : linksBelow(cell.world.model(), robot.tool_link))
      {
        const std::string held = heldLink(cell.world.model(), link, robot.arm_joints);
        EXPECT_TRUE(rigidWithTheArm(cell.world.model(), held, robot.arm_joints)) << link << " -> " << held;
        EXPECT_EQ(heldLink(cell.world.model(), held, robot.arm_joints), held) << held;
      }
    for (const vrrw_scene::Robot& robot : cell.scene.robots)  // an arm link is held as itself
      for (const std::string& joint : robot.arm_joints)
      {
        const vrrw_kinematics::RobotModel& model = cell.world.model();
        const std::string& child = model.links()[model.joints()[model.jointIndex(joint)].child_link].name;
        EXPECT_EQ(heldLink(model, child, robot.arm_joints), child);
      }
  }
  const Cell cell("paper_multibot");
  const vrrw_scene::Robot& fetch = *cell.scene.robot("fetch");
  EXPECT_EQ(heldLink(cell.world.model(), "fetch_l_gripper_finger_link", fetch.arm_joints), "fetch_gripper_link");
}

TEST(GrabTarget, ObjectsOnlyWhereTheyMoveAndNeverTheTable)
{
  Cell& cell = drillCell();
  const Eigen::Vector3d drill = cell.scene.object("drill")->pose.translation();
  GrabRule rule;
  rule.robots = { "ur5e" };
  EXPECT_FALSE(handGrab(cell.world, cell.scene, cell.state, drill, rule));  // fake mode: objects do not move
  rule.movable_objects = true;
  const auto grabbed = handGrab(cell.world, cell.scene, cell.state, drill, rule);
  ASSERT_TRUE(grabbed);
  EXPECT_EQ(grabbed->body, "drill");
  EXPECT_TRUE(grabbed->object);
  EXPECT_EQ(grabbed->distance, 0.0);  // inside: the point itself
  // on the table, 30 cm from anything else: nothing to take
  const Eigen::Vector3d table = drill + Eigen::Vector3d(0, -0.3, -0.05);
  EXPECT_FALSE(handGrab(cell.world, cell.scene, cell.state, table, rule));
  EXPECT_TRUE(clearOfMovingBodies(cell.world, cell.scene, cell.state, table, 0.05));
  EXPECT_FALSE(clearOfMovingBodies(cell.world, cell.scene, cell.state, drill, 0.05));
  const Eigen::Vector3d tcp = cell.link("ur5e_tcp", cell.state).translation();
  EXPECT_FALSE(clearOfMovingBodies(cell.world, cell.scene, cell.state, tcp, 0.05));
}
