#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/input_limits.h>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <stdexcept>

#include "bullet_conversions.h"
#include "collision_shape.h"
#include "link_tree.h"

namespace vrrw_physics
{
ArticulatedRobot::ArticulatedRobot(const urdf::ModelInterface& model, const std::string& name,
                                   const std::string& base_link, const LinkMaterial& material)
  : name_(name)
{
  const std::vector<MergedBody> bodies = mergeFixedLinks(model, base_link, name);
  createMultiBody(bodies, worldPose(model, base_link));
  createColliders(bodies, material);
  createJointRows(model);
  feed_forward_.assign(joints_.size(), 0.0);
  setState(std::vector<double>(joints_.size(), 0.0), std::vector<double>(joints_.size(), 0.0));
}

void ArticulatedRobot::createMultiBody(const std::vector<MergedBody>& bodies, const Eigen::Isometry3d& base_pose)
{
  const int n_links = int(bodies.size()) - 1;
  if (n_links > kMaxJoints)
    throw std::runtime_error("robot " + name_ + ": " + std::to_string(n_links) + " movable joints, at most " +
                             std::to_string(kMaxJoints) + " supported");
  const MergedBody& root = bodies[0];
  const Eigen::Isometry3d base_frame = base_pose * root.root_T_frame;
  try
  {
    requireWorkspacePose(base_frame, "robot " + name_ + ": base");
  }
  catch (const InputError& e)
  {
    throw std::runtime_error(e.what());
  }
  body_ = std::make_unique<btMultiBody>(n_links, btScalar(root.mass), toBullet(root.principal), true, false);
  body_->setBaseWorldTransform(toBullet(base_frame));
  for (int i = 1; i <= n_links; ++i)
    setupLink(i - 1, bodies[std::size_t(i)], bodies[std::size_t(bodies[std::size_t(i)].parent)]);
  body_->finalizeMultiDof();
  body_->setLinearDamping(0);
  body_->setAngularDamping(0);
  body_->setHasSelfCollision(false);
  body_->setCanSleep(false);
}

void ArticulatedRobot::setupLink(int link, const MergedBody& b, const MergedBody& p)
{
  const urdf::Joint& joint = *b.joint;
  const Eigen::Matrix3d parent_R_this =
      p.root_T_frame.rotation().transpose() * b.parent_T_joint.rotation() * b.root_T_frame.rotation();
  const btQuaternion rot_parent_to_this = toBullet(Eigen::Quaterniond(parent_R_this.transpose()));
  const Eigen::Vector3d axis_urdf(joint.axis.x, joint.axis.y, joint.axis.z);
  const btVector3 axis = toBullet(Eigen::Vector3d(b.root_T_frame.rotation().transpose() * axis_urdf.normalized()));
  const btVector3 parent_com_to_pivot = toBullet(Eigen::Vector3d(
      p.root_T_frame.rotation().transpose() * (b.parent_T_joint.translation() - p.root_T_frame.translation())));
  const btVector3 pivot_to_com =
      toBullet(Eigen::Vector3d(b.root_T_frame.rotation().transpose() * b.root_T_frame.translation()));
  const int parent_link = b.parent - 1;
  if (joint.type == urdf::Joint::PRISMATIC)
    body_->setupPrismatic(link, btScalar(b.mass), toBullet(b.principal), parent_link, rot_parent_to_this, axis,
                          parent_com_to_pivot, pivot_to_com, true);
  else
    body_->setupRevolute(link, btScalar(b.mass), toBullet(b.principal), parent_link, rot_parent_to_this, axis,
                         parent_com_to_pivot, pivot_to_com, true);

  SimJoint sim;
  sim.name = joint.name;
  sim.link = link;
  sim.prismatic = joint.type == urdf::Joint::PRISMATIC;
  if (joint.limits)
  {
    sim.limited = joint.type != urdf::Joint::CONTINUOUS && joint.limits->upper > joint.limits->lower;
    sim.lower = joint.limits->lower;
    sim.upper = joint.limits->upper;
    sim.max_effort = joint.limits->effort;
    sim.max_velocity = joint.limits->velocity;
  }
  joints_.push_back(sim);
}

void ArticulatedRobot::createColliders(const std::vector<MergedBody>& bodies, const LinkMaterial& material)
{
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const MergedBody& b = bodies[i];
    const int link = int(i) - 1;
    const Eigen::Isometry3d frame_T_root = b.root_T_frame.inverse();
    for (const auto& l : b.links)
      links_[l.first] = { link, frame_T_root * l.second };
    auto collider = std::make_unique<btMultiBodyLinkCollider>(body_.get(), link);
    collider->setCollisionShape(compoundShape(b));
    collider->setFriction(btScalar(material.friction));
    collider->setRestitution(btScalar(material.restitution));
    collider->setUserIndex(b.parts.empty() ? 0 : 1);
    // Friction anchors: static friction corrects position drift, so a held object does not creep.
    collider->setCollisionFlags(collider->getCollisionFlags() | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    if (link < 0)
      body_->setBaseCollider(collider.get());
    else
      body_->getLink(link).m_collider = collider.get();
    colliders_.push_back(std::move(collider));
  }
}

btCollisionShape* ArticulatedRobot::compoundShape(const MergedBody& b)
{
  const Eigen::Isometry3d frame_T_root = b.root_T_frame.inverse();
  auto compound = std::make_unique<btCompoundShape>(true, int(b.parts.size()));
  std::vector<std::string> shape_links;
  for (const CollisionPart& part : b.parts)
  {
    try
    {
      shapes_.push_back(makeCollisionShape(part.shape));
    }
    catch (const std::runtime_error& e)
    {
      throw std::runtime_error("robot " + name_ + ": link " + part.link + ": collision " + e.what());
    }
    compound->addChildShape(toBullet(frame_T_root * part.shape.origin), shapes_.back().get());
    shape_links.push_back(part.link);
  }
  if (b.parts.empty())
  {
    // A link without collision geometry still needs a collider: Bullet solves constraints per island.
    shapes_.emplace_back(new btSphereShape(btScalar(0.001)));
    compound->addChildShape(btTransform::getIdentity(), shapes_.back().get());
  }
  shape_links_.push_back({ b.links.front().first, shape_links });
  shapes_.push_back(std::move(compound));
  return shapes_.back().get();
}

void ArticulatedRobot::createJointRows(const urdf::ModelInterface& model)
{
  response_.joint_of_dof.assign(std::size_t(body_->getNumDofs()), -1);
  for (std::size_t j = 0; j < joints_.size(); ++j)
    response_.joint_of_dof[std::size_t(body_->getLink(joints_[j].link).m_dofOffset)] = int(j);
  coupling_of_joint_.assign(joints_.size(), -1);
  std::vector<JointRange> ranges;
  for (std::size_t j = 0; j < joints_.size(); ++j)
  {
    SimJoint& sim = joints_[j];
    if (sim.limited)
      ranges.push_back({ sim.link, sim.lower, sim.upper });
    const urdf::JointConstSharedPtr joint = model.getJoint(sim.name);
    if (joint->mimic)
    {
      addCoupling(j, *joint->mimic);
      continue;
    }
    sim.drive = int(drives_.size());
    drives_.push_back(std::make_unique<JointDrive>(body_.get(), sim.link, &response_));
    if (sim.max_effort > 0.0)
      drives_.back()->setForceLimit(sim.max_effort);
  }
  if (!ranges.empty())
    limits_ = std::make_unique<JointLimits>(body_.get(), ranges, &response_);
}

void ArticulatedRobot::addCoupling(std::size_t joint, const urdf::JointMimic& mimic)
{
  SimJoint& sim = joints_[joint];
  const int master = jointIndex(mimic.joint_name);
  if (master < 0)
    throw std::runtime_error("joint " + sim.name + ": mimics '" + mimic.joint_name +
                             "', not a movable joint of robot " + name_);
  auto coupling = std::make_unique<JointCoupling>(body_.get(), sim.link, joints_[std::size_t(master)].link,
                                                  mimic.multiplier, mimic.offset, &response_);
  // Stiff enough that the linkage moves as one, soft enough for Gauss-Seidel to converge.
  coupling->setGains(1e7, 1e4);
  sim.mimic = master;
  sim.multiplier = mimic.multiplier;
  sim.offset = mimic.offset;
  coupling_of_joint_[joint] = int(couplings_.size());
  couplings_.push_back(std::move(coupling));
  sim.mimic_drive = int(mimic_drives_.size());
  mimic_drives_.push_back(std::make_unique<JointDrive>(body_.get(), sim.link, &response_));
}

ArticulatedRobot::~ArticulatedRobot()
{
  if (!world_)
    return;
  world_->removeMultiBodyConstraint(rows_.get());
  for (auto& c : colliders_)
    world_->removeCollisionObject(c.get());
  world_->removeMultiBody(body_.get());
}

void ArticulatedRobot::addToWorld(btMultiBodyDynamicsWorld* world, bool drive_constraints)
{
  world_ = world;
  drive_constraints_ = drive_constraints;
  world->addMultiBody(body_.get());
  for (auto& c : colliders_)
  {
    const bool solid = c->getUserIndex() == 1;
    const bool base = c->m_link < 0;
    const int group = base ? int(btBroadphaseProxy::StaticFilter) : int(btBroadphaseProxy::DefaultFilter);
    const int mask = solid ? (base ? int(btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter)
                                   : int(btBroadphaseProxy::AllFilter))
                           : 0;
    world->addCollisionObject(c.get(), solid ? group : 0, mask);
  }
  // Row order matters to Gauss-Seidel: drives before the couplings they feed converge fastest.
  rows_ = std::make_unique<JointRowGroup>(body_.get());
  if (limits_)
    rows_->add(limits_.get());
  if (drive_constraints)
  {
    for (auto& d : drives_)
      rows_->add(d.get());
    for (auto& d : mimic_drives_)
      rows_->add(d.get());
  }
  for (auto& c : couplings_)
    rows_->add(c.get());
  world->addMultiBodyConstraint(rows_.get());
}
}  // namespace vrrw_physics
