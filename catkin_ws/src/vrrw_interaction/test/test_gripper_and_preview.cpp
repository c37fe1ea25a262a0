// Which way a gripper closes (gripper.h), the plan preview (plan_preview.h) and the ghost's tint
// (ghost_description.h) on the shipped cells (no ROS).
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_interaction/ghost_description.h>
#include <vrrw_interaction/gripper.h>
#include <vrrw_interaction/interaction_error.h>
#include <vrrw_interaction/plan_preview.h>
#include <vrrw_kinematics/time_parameterization.h>

#include "library_fixture.h"

using namespace vrrw_interaction;
using vrrw_interaction_test::Cell;

TEST(Gripper, ARobotiqClosesWithTheAngleFetchClosesTheGap)
{
  const Cell cell("paper_multibot");
  const vrrw_kinematics::RobotModel& model = cell.world.model();
  const GripperRange robotiq = *gripperRange(model, *cell.scene.robot("ur5e"));
  const vrrw_kinematics::JointModel& knuckle = model.joints()[model.jointIndex("ur5e_finger_joint")];
  EXPECT_EQ(robotiq.joint, "ur5e_finger_joint");
  EXPECT_EQ(robotiq.open, knuckle.lower);
  EXPECT_EQ(robotiq.closed, knuckle.upper);
  EXPECT_GT(robotiq.closed, robotiq.open);
  const GripperRange fetch = *gripperRange(model, *cell.scene.robot("fetch"));
  const vrrw_kinematics::JointModel& finger = model.joints()[model.jointIndex("fetch_l_gripper_finger_joint")];
  EXPECT_EQ(fetch.open, finger.upper);
  EXPECT_EQ(fetch.closed, finger.lower);
  EXPECT_DOUBLE_EQ(fetch.closedFraction(finger.upper), 0.0);
  EXPECT_DOUBLE_EQ(fetch.closedFraction(finger.lower), 1.0);
  EXPECT_DOUBLE_EQ(robotiq.closedFraction(0.25 * knuckle.upper), 0.25);
  vrrw_scene::Robot bare = *cell.scene.robot("ur5e");
  bare.gripper_joints.clear();
  EXPECT_FALSE(gripperRange(model, bare));
}

TEST(PlanPreview, PlaysThePlanAsTheControllerInterpolatesItThenHoldsItsEnd)
{
  vrrw_kinematics::TimingOptions timing;
  timing.max_velocity.assign(2, 1.0);
  timing.max_acceleration.assign(2, 2.0);
  const vrrw_trajectory::JointTrajectory plan = vrrw_kinematics::TimeParameterization(timing).compute(
      { Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0.5), Eigen::Vector2d(0.5, 1.5) }, { "a", "b" });
  const vrrw_control::TrajectoryInterpolator controller(plan);
  PlanPreview preview;
  EXPECT_FALSE(preview.at(0.0));
  preview.play(plan, 100.0);
  const double end = plan.duration();
  double largest = 0.0;
  for (double t = 0.0; t <= end; t += 0.0037)  // between the samples too: the controller's spline, not lines
  {
    const std::vector<double> q = controller.sample(t).positions;
    largest = std::max(largest, (*preview.at(100.0 + t) - Eigen::Vector2d(q[0], q[1])).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(largest, 1e-12);  // (the clock offset rounds)
  const Eigen::Vector2d last(0.5, 1.5);
  EXPECT_LT((*preview.at(100.0 + end + 0.49) - last).norm(), 1e-12);  // held at the end
  EXPECT_FALSE(preview.at(100.0 + end + PlanPreview::kHold + 1e-6));
  preview.play(plan, 200.0);
  preview.stop();
  EXPECT_FALSE(preview.at(200.1));
}

TEST(GhostDescription, EveryRobotsLinksInItsOwnTint)
{
  const Cell cell("paper_multibot");
  const std::string description = ghostDescription(cell.scene);
  const vrrw_kinematics::RobotModel ghost = vrrw_kinematics::RobotModel::fromUrdf(description);
  EXPECT_EQ(ghost.links().size(), cell.world.model().links().size());
  EXPECT_EQ(ghost.joints().size(), cell.world.model().joints().size());
  for (std::size_t r = 0; r < cell.scene.robots.size(); ++r)
  {
    const Tint tint = ghostTint(r);
    char rgba[64];
    std::snprintf(rgba, sizeof(rgba), "rgba=\"%.3f %.3f %.3f 1\"", tint.r, tint.g, tint.b);
    EXPECT_NE(description.find("<material name=\"ghost_" + cell.scene.robots[r].name + "\">"), std::string::npos);
    EXPECT_NE(description.find(rgba), std::string::npos) << rgba;
  }
  // four robots, four tints, none of them grey
  for (std::size_t a = 0; a < 4; ++a)
  {
    const Tint t = ghostTint(a);
    EXPECT_GT(std::max({ t.r, t.g, t.b }) - std::min({ t.r, t.g, t.b }), 0.5) << a;
    for (std::size_t b = 0; b < a; ++b)
      EXPECT_GT(std::abs(t.r - ghostTint(b).r) + std::abs(t.g - ghostTint(b).g) + std::abs(t.b - ghostTint(b).b), 0.5);
  }
  // every visual of a robot link is tinted: as many tinted materials as robot visuals
  std::size_t visuals = 0, tinted = 0;
  for (std::size_t at = cell.scene.urdf.find("<visual"); at != std::string::npos; at = cell.scene.urdf.find("<visual", at + 1))
    ++visuals;
  for (std::size_t at = description.find("<material name=\"ghost_"); at != std::string::npos;
       at = description.find("<material name=\"ghost_", at + 1))
    ++tinted;
  EXPECT_EQ(tinted, visuals);
  vrrw_scene::Scene broken = cell.scene;
  broken.urdf = "<robot";
  EXPECT_THROW(ghostDescription(broken), InteractionError);
}
