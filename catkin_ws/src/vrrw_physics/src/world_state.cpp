// PhysicsWorld: its state, the guard that checks every step, and the way back (guard trips, reset).
#include <vrrw_physics/physics_world.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <cmath>
#include <sstream>

namespace vrrw_physics
{
WorldState PhysicsWorld::snapshot() const
{
  WorldState s;
  s.time = time_;
  s.steps = steps_;
  for (const RobotEntry& e : robots_)
  {
    s.positions.push_back(e.robot->positions());
    s.velocities.push_back(e.robot->velocities());
    std::vector<double> tp, tv;
    for (const auto& d : e.robot->drives())
    {
      tp.push_back(d->targetPosition());
      tv.push_back(d->targetVelocity());
    }
    s.target_positions.push_back(tp);
    s.target_velocities.push_back(tv);
  }
  for (const auto& o : objects_)
  {
    s.object_poses.push_back(o->pose());
    s.object_linear.push_back(o->linearVelocity());
    s.object_angular.push_back(o->angularVelocity());
  }
  return s;
}

void PhysicsWorld::restore(const WorldState& s)
{
  time_ = s.time;
  steps_ = s.steps;
  restoreMotion(s);
}

void PhysicsWorld::restoreMotion(const WorldState& s)
{
  for (std::size_t r = 0; r < robots_.size() && r < s.positions.size(); ++r)
  {
    ArticulatedRobot& robot = *robots_[r].robot;
    robot.setState(s.positions[r], s.velocities[r]);
    for (std::size_t d = 0; d < robot.drives().size(); ++d)
      robot.drives()[d]->setTarget(s.target_positions[r][d], s.target_velocities[r][d]);
    robots_[r].drives->endStream();
  }
  for (std::size_t o = 0; o < objects_.size() && o < s.object_poses.size(); ++o)
  {
    objects_[o]->setPose(s.object_poses[o]);
    objects_[o]->setVelocity(s.object_linear[o], s.object_angular[o]);
  }
}

void PhysicsWorld::reset()
{
  // A new Bullet world from the scene, not the old one's bodies put back: Bullet keeps more between steps than
  // the bodies' states (the broadphase's tree and pair order, contact manifolds with their warm-start impulses,
  // sleeping timers), and any of it left from before made the same inputs give other states after a reset
  // (two replays of one demonstration differed from 0.1 s on).
  tearDown();
  time_ = 0.0;
  steps_ = 0;
  build();
  last_good_ = initial_;
  trips_in_a_row_ = 0;
  tripped_since_snapshot_ = false;
  stopped_ = false;
  last_error_.clear();
}

std::string PhysicsWorld::insaneState() const
{
  // Checked every step: no allocation or stream unless something is wrong.
  for (const RobotEntry& e : robots_)
  {
    const btMultiBody& body = *e.robot->body();
    for (const SimJoint& joint : e.robot->joints())
    {
      const double q = body.getJointPos(joint.link);
      const double v = body.getJointVel(joint.link);
      if (!std::isfinite(q) || !std::isfinite(v) || std::abs(v) > options_.max_joint_speed)
      {
        std::ostringstream text;
        text << "joint " << joint.name << ": position " << q << ", velocity " << v << " (limit "
             << options_.max_joint_speed << ")";
        return text.str();
      }
    }
  }
  for (const auto& o : objects_)
  {
    const Eigen::Vector3d p = o->pose().translation();
    const double speed = o->linearVelocity().norm();
    if (!p.allFinite() || !std::isfinite(speed) || speed > options_.max_object_speed)
    {
      std::ostringstream text;
      text << "object " << o->name() << ": speed " << speed << " m/s (limit " << options_.max_object_speed << ")";
      return text.str();
    }
  }
  return "";
}

void PhysicsWorld::recoverFrom(const std::string& why)
{
  std::ostringstream message;
  message << "physics guard at t=" << time_ << " s: " << why << "; step rejected, state of t=" << last_good_.time
          << " s restored";
  std::string released;
  for (const std::string& id : operator_->springs())
    released += (released.empty() ? "" : ", ") + ("spring '" + id + "'");
  for (const std::string& id : operator_->hands())
    released += (released.empty() ? "" : ", ") + ("hand '" + id + "'");
  if (!released.empty())
    message << ", released " << released;
  operator_->releaseHandsAndSprings();
  restoreMotion(last_good_);
  tripped_since_snapshot_ = true;
  if (++trips_in_a_row_ >= options_.max_guard_trips)
  {
    stopped_ = true;
    message << "; stopped after " << trips_in_a_row_ << " trips without a good state between: call reset";
  }
  last_error_ = message.str();
  reports_.push_back(last_error_);
}
}  // namespace vrrw_physics
