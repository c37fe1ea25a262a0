// Both "is it held" rules and the attach/detach bookkeeping (held_objects.h) on pick_place_drill (no ROS).
#include <vrrw_interaction/held_objects.h>
#include <vrrw_kinematics/top_grasp.h>

#include "library_fixture.h"

using namespace vrrw_interaction;
using vrrw_interaction_test::Cell;

namespace
{
const std::vector<std::string> kPads = { "ur5e_left_inner_finger_pad", "ur5e_right_inner_finger_pad" };

BodyContact press(const std::string& a, const std::string& b, const Eigen::Vector3d& at, double force)
{
  return { a, b, at, force };
}

/// The UR5e with its TCP over the drill's housing, fingers across it (vrrw_evaluation's grasp), `above` m
/// higher, the gripper at `closed` (fraction).
Eigen::VectorXd atTheDrill(Cell& cell, double above, double closed)
{
  const vrrw_scene::Robot& robot = *cell.scene.robot("ur5e");
  vrrw_kinematics::Arm arm(cell.world, robot);
  Eigen::Isometry3d tcp = vrrw_kinematics::topGrasp(cell.scene.object("drill")->pose, Eigen::Vector3d(0.03, 0.0, 0.203));
  tcp.translation().z() += above;
  const vrrw_kinematics::IkResult ik =
      arm.ikSolver().solve(arm.basePose(cell.state).inverse() * tcp, arm.jointValues(cell.state), {});
  EXPECT_TRUE(ik.success) << ik.message;
  Eigen::VectorXd state = arm.withJointValues(cell.state, ik.q);
  const GripperRange range = *gripperRange(cell.world.model(), robot);
  state[cell.world.model().variableIndex(range.joint)] = range.open + closed * (range.closed - range.open);
  return state;
}
}  // namespace

TEST(HeldObjects, PhysicsRuleTwoFingersSqueezeFromOppositeSides)
{
  const Eigen::Vector3d tcp(0.1, 0.2, 1.0), y = Eigen::Vector3d::UnitY();
  const std::vector<std::string>& pads = kPads;
  EXPECT_TRUE(fingersSqueeze("drill", { press("drill", pads[0], tcp - 0.02 * y, 0.5), press(pads[1], "drill", tcp + 0.02 * y, 3.0) },
                             pads, tcp));
  // one side only (a finger resting on it), a light touch, another link, another object
  EXPECT_FALSE(fingersSqueeze("drill", { press("drill", pads[0], tcp - 0.02 * y, 5), press("drill", pads[1], tcp - 0.01 * y, 5) },
                              pads, tcp));
  EXPECT_FALSE(fingersSqueeze("drill", { press("drill", pads[0], tcp - 0.02 * y, 0.49), press("drill", pads[1], tcp + 0.02 * y, 5) },
                              pads, tcp));
  EXPECT_FALSE(fingersSqueeze("drill", { press("drill", "ur5e_wrist_3_link", tcp - 0.02 * y, 5), press("drill", pads[1], tcp + 0.02 * y, 5) },
                              pads, tcp));
  EXPECT_FALSE(fingersSqueeze("drill", { press("cube", pads[0], tcp - 0.02 * y, 5), press("cube", pads[1], tcp + 0.02 * y, 5) },
                              pads, tcp));
}

TEST(HeldObjects, FakeRuleTheGripperClosedAtTheObject)
{
  Cell cell("pick_place_drill");
  const vrrw_scene::Robot& robot = *cell.scene.robot("ur5e");
  const GripperRange range = *gripperRange(cell.world.model(), robot);
  EXPECT_TRUE(closedGripperHolds(cell.world, atTheDrill(cell, 0.0, 0.31), robot, range, "drill"));
  EXPECT_FALSE(closedGripperHolds(cell.world, atTheDrill(cell, 0.0, 0.29), robot, range, "drill"));  // not closed enough
  EXPECT_FALSE(closedGripperHolds(cell.world, atTheDrill(cell, 0.1, 0.8), robot, range, "drill"));   // closed in the air
  EXPECT_FALSE(closedGripperHolds(cell.world, atTheDrill(cell, 0.0, 0.8), robot, range, "bin"));
}

TEST(HeldObjects, AttachedOnTheRuleDetachedAfterLettingGoTheTableAllowedUntilLifted)
{
  Cell cell("pick_place_drill");
  HeldObjects held(cell.world, cell.scene);
  const std::vector<std::string>& gripper = held.gripperLinks("ur5e");
  EXPECT_NE(std::find(gripper.begin(), gripper.end(), kPads[0]), gripper.end());
  EXPECT_TRUE(held.gripperLinks("ur10e").empty());
  const Eigen::VectorXd grasp = atTheDrill(cell, 0.0, 0.8);
  ASSERT_EQ(held.heldByClosedGripper("drill", grasp), "ur5e");
  const std::vector<HeldEvent> attach = held.update("drill", "ur5e", grasp, 10.0);
  ASSERT_EQ(attach.size(), 1u);
  EXPECT_EQ(attach[0].kind, "attach");
  EXPECT_EQ(attach[0].detail, "drill to ur5e_tcp (touching table until lifted 1 cm)");
  EXPECT_EQ(held.holder("drill"), "ur5e");
  EXPECT_TRUE(cell.world.acm().allowed("drill", kPads[0]));
  EXPECT_TRUE(cell.world.acm().allowed("drill", "table"));
  held.releaseLifted(atTheDrill(cell, 0.005, 0.8));  // 5 mm: still on its way up
  EXPECT_TRUE(cell.world.acm().allowed("drill", "table"));
  held.releaseLifted(atTheDrill(cell, 0.02, 0.8));   // lifted: the table counts again
  EXPECT_FALSE(cell.world.acm().allowed("drill", "table"));
  EXPECT_TRUE(held.update("drill", "", grasp, 10.29).empty());  // not yet let go
  const std::vector<HeldEvent> detach = held.update("drill", "", grasp, 10.31);
  ASSERT_EQ(detach.size(), 1u);
  EXPECT_EQ(detach[0].kind, "detach");
  EXPECT_EQ(detach[0].detail, "drill from ur5e_tcp");
  EXPECT_EQ(held.holder("drill"), "");
  EXPECT_TRUE(cell.world.acm().allowed("drill", "table"));  // standing on it again, as before the grasp
  EXPECT_FALSE(cell.world.acm().allowed("drill", kPads[0]));
}

TEST(HeldObjects, PlaceContactAllowsExactlyWhatItTakesBack)
{
  Cell cell("pick_place_drill");
  HeldObjects held(cell.world, cell.scene);
  const Eigen::VectorXd lifted = atTheDrill(cell, 0.02, 0.8);
  held.update("drill", "ur5e", atTheDrill(cell, 0.0, 0.8), 0.0);
  held.releaseLifted(lifted);
  ASSERT_FALSE(cell.world.acm().allowed("drill", "table"));
  held.allowPlaceContact("ur5e", "table", true);
  EXPECT_TRUE(cell.world.acm().allowed("drill", "table"));
  EXPECT_FALSE(cell.world.acm().allowed("drill", "bin"));
  held.allowPlaceContact("ur5e", "table", false);
  EXPECT_FALSE(cell.world.acm().allowed("drill", "table"));
  held.allowPlaceContact("ur10e", "table", true);  // holds nothing
  EXPECT_FALSE(cell.world.acm().allowed("drill", "table"));
}
