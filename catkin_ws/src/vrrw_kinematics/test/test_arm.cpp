// Arm on the shipped paper_multibot cell: IK the scene accepts, with the other robots at their live states.
#include <gtest/gtest.h>

#include <random>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_scene/scene_loader.h>

using namespace vrrw_kinematics;

namespace
{
bool touches(const Contact& contact, const std::string& prefix)
{
  return contact.collision && (contact.body_a.rfind(prefix, 0) == 0 || contact.body_b.rfind(prefix, 0) == 0);
}

class ArmTest : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    scene_ = new vrrw_scene::Scene(vrrw_scene::loadScene("paper_multibot"));
    world_ = new CollisionWorld(CollisionWorld::fromScene(*scene_));
    world_->loadOrComputeAllowedCollisions(scene_->cache_dir);
  }
  static void TearDownTestSuite()
  {
    delete world_;
    delete scene_;
  }

  ArmTest() : initial_(initialState(world_->model(), *scene_)), ur5e_(*world_, *scene_->robot("ur5e")) {}

  /// A random configuration of `arm` that touches nothing with the rest of the world at `state`.
  Eigen::VectorXd freeConfiguration(Arm& arm, const Eigen::VectorXd& state, std::mt19937_64& rng)
  {
    for (int attempt = 0; attempt < 10000; ++attempt)
    {
      const Eigen::VectorXd q = arm.ikSolver().chain().randomState(rng);
      if (!arm.check(q, state).collision)
        return q;
    }
    ADD_FAILURE() << "no free configuration of " << arm.robot().name;
    return arm.jointValues(state);
  }

  Eigen::Isometry3d tcpInWorld(Arm& arm, const Eigen::VectorXd& q, const Eigen::VectorXd& state)
  {
    return arm.basePose(state) * arm.ikSolver().chain().fk(q);
  }

  static vrrw_scene::Scene* scene_;
  static CollisionWorld* world_;
  Eigen::VectorXd initial_;
  Arm ur5e_;
};

vrrw_scene::Scene* ArmTest::scene_ = nullptr;
CollisionWorld* ArmTest::world_ = nullptr;
}  // namespace

TEST_F(ArmTest, JointValuesAreTheArmsVariables)
{
  ASSERT_EQ(ur5e_.size(), 6u);
  EXPECT_EQ(ur5e_.baseLink(), "ur5e_base_link_inertia");
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(6, 0.1, 0.6);
  const Eigen::VectorXd state = ur5e_.withJointValues(initial_, q);
  EXPECT_EQ(ur5e_.jointValues(state), q);
  const int pan = world_->model().variableIndex("ur5e_shoulder_pan_joint");
  EXPECT_EQ(state[pan], 0.1);
  EXPECT_EQ(ur5e_.timing().max_acceleration.size(), 6u);
  EXPECT_EQ(ur5e_.bounds().violation(q), "");
  EXPECT_NE(ur5e_.bounds().violation(Eigen::VectorXd::Constant(6, 7.0)).find("ur5e_shoulder_pan_joint"),
            std::string::npos);
}

TEST_F(ArmTest, SolvesWorldTargetsNearTheSeed)
{
  std::mt19937_64 rng(11);
  IkOptions options;
  options.max_jump = 0.5;
  for (int s = 0; s < 50; ++s)
  {
    const Eigen::VectorXd q = freeConfiguration(ur5e_, initial_, rng);
    const Eigen::Isometry3d target = tcpInWorld(ur5e_, q, initial_);
    const IkResult result = ur5e_.solveCollisionFree(target, q + Eigen::VectorXd::Constant(6, 0.02), initial_, options);
    ASSERT_TRUE(result.success) << result.message;
    EXPECT_LT((result.q - q).cwiseAbs().maxCoeff(), 1e-6);
    const Eigen::Isometry3d reached = tcpInWorld(ur5e_, result.q, initial_);
    EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-6);
    EXPECT_LT(rotationError(target.linear(), reached.linear()).norm(), 1e-6);
    EXPECT_FALSE(world_->check(ur5e_.withJointValues(initial_, result.q), "ur5e").collision);
  }
}

TEST_F(ArmTest, AnotherRobotAtItsLiveStateBlocksTheTarget)
{
  // Find a UR5e configuration that the UR3e, moved to some live state, occupies.
  Arm ur3e(*world_, *scene_->robot("ur3e"));
  std::mt19937_64 rng(5);
  IkOptions options;
  options.max_jump = 0.3;
  for (int attempt = 0; attempt < 20000; ++attempt)
  {
    const Eigen::VectorXd q5 = freeConfiguration(ur5e_, initial_, rng);
    const Eigen::VectorXd live = ur3e.withJointValues(initial_, ur3e.ikSolver().chain().randomState(rng));
    if (!touches(ur5e_.check(q5, live), "ur3e_"))
      continue;
    const Eigen::Isometry3d target = tcpInWorld(ur5e_, q5, initial_);
    const IkResult blocked = ur5e_.solveCollisionFree(target, q5, live, options);
    ASSERT_EQ(blocked.code, ErrorCode::InCollision) << blocked.message;
    EXPECT_TRUE(touches(blocked.contact, "ur3e_")) << blocked.contact.body_a << " - " << blocked.contact.body_b;
    EXPECT_TRUE(touches(blocked.contact, "ur5e_")) << blocked.contact.body_a << " - " << blocked.contact.body_b;
    const IkResult free = ur5e_.solveCollisionFree(target, q5, initial_, options);  // the UR3e back home
    ASSERT_TRUE(free.success) << free.message;
    EXPECT_LT((free.q - q5).cwiseAbs().maxCoeff(), 1e-6);
    return;
  }
  FAIL() << "no UR3e state found that blocks a UR5e configuration";
}

TEST_F(ArmTest, AMovedObjectIsSeenAtOnce)
{
  CollisionWorld world = CollisionWorld::fromScene(*scene_);
  world.loadOrComputeAllowedCollisions(scene_->cache_dir);
  Arm ur5e(world, *scene_->robot("ur5e"));
  std::mt19937_64 rng(2);
  const Eigen::VectorXd q = freeConfiguration(ur5e, initial_, rng);
  const Eigen::Isometry3d target = tcpInWorld(ur5e, q, initial_);
  ASSERT_TRUE(ur5e.solveCollisionFree(target, q, initial_).success);
  world.setObjectPose("cube", target);  // the cube where the tcp wants to go
  const IkResult blocked = ur5e.solveCollisionFree(target, q, initial_);
  EXPECT_EQ(blocked.code, ErrorCode::InCollision) << blocked.message;
  EXPECT_TRUE(blocked.contact.body_a == "cube" || blocked.contact.body_b == "cube")
      << blocked.contact.body_a << " - " << blocked.contact.body_b;
}

TEST_F(ArmTest, UnreachableWorldTargetReportsTheResidual)
{
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 0.0, -3.0, 0.9;
  const IkResult result = ur5e_.solveCollisionFree(far, ur5e_.jointValues(initial_), initial_);
  EXPECT_EQ(result.code, ErrorCode::NoSolution);
  EXPECT_GT(result.position_error, 1.5);
}
