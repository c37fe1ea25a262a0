// vrrw_bench_skill: how long `skill learn` takes on a bag, and how long planning one trial of `skill run` takes
// (IK of every goal, the DMP rollouts, every state checked for collisions) with vrrw_kinematics in-process, the
// same work the planning node does behind its services. Progress on stderr, last line JSON.
//   vrrw_bench_skill --bag BAG --object NAME [--scene pick_place_drill] [--arm R] [--trials 20] [--seed 1]
//                    [--spread DX,DY,DYAW_DEG] [--repetitions 5]
// --arm: the scene's robot that plans (default the taught one; another arm follows the Cartesian DMPs by IK).
// "planned": the poses whose every goal has a collision-free IK and whose every motion is free (what a trial needs
// before it can run), so --spread 0.15,0.15,60 says how much of that spread the arm can do at all.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <vrrw_common/options.h>
#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/collision_world.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_scene/scene_loader.h>
#include <vrrw_skills/evaluation.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_learning.h>
#include <vrrw_skills/skill_plan.h>
#include <vrrw_skills/trial_outcome.h>

namespace
{
using Clock = std::chrono::steady_clock;
using vrrw_skills::CartesianPose;

double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The planner's arm on vrrw_kinematics directly: what the planning node answers compute_ik, check_path and
/// compute_fk with, without the service round trips.
class LibraryArm : public vrrw_skills::ArmKinematics
{
public:
  LibraryArm(vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Robot& robot, Eigen::VectorXd state)
    : world_(world), arm_(world, robot), state_(std::move(state))
  {
  }

  vrrw_skills::IkAnswer ik(const CartesianPose& tcp, const std::vector<double>& seed, bool avoid_collisions) override
  {
    vrrw_kinematics::IkOptions options;
    options.timeout = 0.02;
    const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(seed.data(), static_cast<Eigen::Index>(seed.size()));
    const Eigen::Isometry3d target = vrrw_skills::toIsometry(tcp);
    const auto result = avoid_collisions ? arm_.solveCollisionFree(target, start, state_, options)
                                         : arm_.ikSolver().solve(arm_.basePose(state_).inverse() * target, start, options);
    if (!result.success)
      return { std::nullopt, result.message };
    return { std::vector<double>(result.q.data(), result.q.data() + result.q.size()), "" };
  }

  std::vector<vrrw_skills::ContactPair> checkPath(const std::vector<std::vector<double>>& path) override
  {
    std::vector<vrrw_skills::ContactPair> pairs;
    for (const auto& joints : path)
    {
      const auto contact = arm_.check(vector(joints), state_);
      pairs.push_back(contact.collision ? vrrw_skills::ContactPair{ contact.body_a, contact.body_b }
                                        : vrrw_skills::ContactPair{});
    }
    return pairs;
  }

  CartesianPose tcp(const std::vector<double>& joints) override
  {
    return vrrw_skills::toPose(arm_.basePose(state_) * arm_.ikSolver().chain().fk(vector(joints)));
  }

  /// \brief The arm's joints in the scene's initial state.
  Eigen::VectorXd home() const { return arm_.jointValues(state_); }

  /// \brief The object at \a pose, free; then held by the TCP at \a grasp (the arm's joints there).
  void place(const std::string& object, const Eigen::Isometry3d& pose) { world_.setObjectPose(object, pose); }
  void hold(const std::string& object, const std::vector<double>& grasp, const std::string& tcp_link,
            const std::vector<std::string>& fingers)
  {
    world_.attachObject(object, tcp_link, arm_.withJointValues(state_, vector(grasp)), fingers);
  }
  void release(const std::string& object) { world_.detachObject(object, state_); }

private:
  static Eigen::VectorXd vector(const std::vector<double>& q)
  {
    return Eigen::Map<const Eigen::VectorXd>(q.data(), static_cast<Eigen::Index>(q.size()));
  }

  vrrw_kinematics::CollisionWorld& world_;
  vrrw_kinematics::Arm arm_;
  Eigen::VectorXd state_;
};
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options options(argc, argv, 1,
                                       { "bag", "object", "scene", "arm", "trials", "seed", "spread", "repetitions" });
    const std::string bag = options.text("bag");
    vrrw_skills::LearnOptions learn;
    learn.object = options.text("object");
    const std::size_t repetitions = options.count("repetitions", 5, 1, 1000);

    std::vector<double> learn_ms;
    vrrw_skills::Skill skill;
    for (std::size_t r = 0; r < repetitions; ++r)
    {
      const auto start = Clock::now();
      skill = vrrw_skills::learnSkill({ vrrw_demos::readDemonstration(bag) }, learn);
      learn_ms.push_back(millisecondsSince(start));
    }
    std::cerr << "vrrw_bench_skill: learned " << bag << " in " << median(learn_ms) << " ms (median of " << repetitions
              << ")\n";

    const vrrw_scene::Scene scene = vrrw_scene::loadScene(options.text("scene", "pick_place_drill"));
    auto world = vrrw_kinematics::CollisionWorld::fromScene(scene);
    world.loadOrComputeAllowedCollisions(scene.cache_dir);
    const std::string arm_name = options.text("arm", skill.robot);
    const auto robot = std::find_if(scene.robots.begin(), scene.robots.end(),
                                    [&](const vrrw_scene::Robot& r) { return r.name == arm_name; });
    if (robot == scene.robots.end())
      throw std::invalid_argument("--scene: no robot '" + arm_name + "'");
    const Eigen::VectorXd state = vrrw_kinematics::initialState(world.model(), scene);
    LibraryArm arm(world, *robot, state);
    std::vector<std::string> fingers;
    for (const auto& link : world.model().links())
      if (vrrw_skills::isFingerLink(link.name) && link.name.rfind(robot->name + "_", 0) == 0)
        fingers.push_back(link.name);

    vrrw_skills::EvaluationOptions trials;
    trials.trials = options.count("trials", 20, 1, 1000);
    trials.seed = options.count("seed", 1, 0, vrrw_common::Options::kMaxCount);
    if (options.has("spread"))
    {
      const auto spread = options.list("spread", 3, vrrw_common::Range::closed(0.0, 1e3));
      trials.spread = { spread[0], spread[1], spread[2] * M_PI / 180.0 };
    }
    std::vector<double> plan_ms;
    std::size_t planned = 0;
    for (const auto& pose : vrrw_skills::evaluationPoses(skill, trials))
    {
      vrrw_skills::SkillScene here;
      here.robot = robot->name;
      here.max_acceleration = vrrw_kinematics::armAccelerationLimits(*robot);
      for (const std::string& joint : robot->arm_joints)
        here.max_velocity.push_back(
            world.model().joints()[static_cast<std::size_t>(world.model().jointIndex(joint))].max_velocity);
      here.arm_joints = robot->arm_joints;
      const Eigen::VectorXd home = arm.home();
      here.joints.assign(home.data(), home.data() + home.size());
      here.object = vrrw_skills::toPose(vrrw_skills::placeOnTable(vrrw_skills::toIsometry(skill.object_start), pose));
      arm.place(skill.object, vrrw_skills::toIsometry(here.object));
      vrrw_skills::SkillPlanner planner(skill, arm);
      const auto start = Clock::now();
      bool held = false;
      try
      {
        planner.approach(here);
        arm.hold(skill.object, planner.goals().at("pick"), robot->tcp_link, fingers);
        held = true;
        here.joints = planner.goals().at("pick");
        planner.carry(here, skill.object_in_hand);
        ++planned;
      }
      catch (const vrrw_skills::SkillRefusal& e)
      {
        std::cerr << "vrrw_bench_skill: refused: " << e.what() << "\n";
      }
      plan_ms.push_back(millisecondsSince(start));
      if (held)
        arm.release(skill.object);
    }
    std::printf("vrrw_bench_skill: %zu of %zu trials planned, median %.1f ms each (IK, rollouts, collision checks)\n",
                planned, plan_ms.size(), median(plan_ms));
    std::printf("{\"bench\":\"skill\",\"bag\":\"%s\",\"learn_ms\":%.1f,\"plan_ms\":%.2f,\"plan_ms_max\":%.2f,"
                "\"trials\":%zu,\"planned\":%zu,\"spread\":[%g,%g,%g],\"target_learn_ms\":2000,"
                "\"target_plan_ms\":100}\n",
                bag.c_str(), median(learn_ms), median(plan_ms), *std::max_element(plan_ms.begin(), plan_ms.end()),
                plan_ms.size(), planned, trials.spread.x, trials.spread.y, trials.spread.yaw * 180.0 / M_PI);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_skill: " << e.what() << "\n";
    return 2;
  }
}
