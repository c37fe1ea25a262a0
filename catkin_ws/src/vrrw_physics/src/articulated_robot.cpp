#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/mesh_shape.h>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

namespace vrrw_physics
{
namespace
{
struct CollisionPart
{
  Eigen::Isometry3d pose;  ///< in the body's root link frame
  urdf::GeometrySharedPtr geometry;
  std::string link;
};

/// A rigid group of URDF links joined by fixed joints, rooted at one link.
struct MergedBody
{
  int parent = -1;  ///< index into the body list; -1 for the base
  urdf::JointConstSharedPtr joint;
  Eigen::Isometry3d parent_T_joint = Eigen::Isometry3d::Identity();  ///< in the parent's root link frame
  double mass = 0.0;
  Eigen::Vector3d mass_moment = Eigen::Vector3d::Zero();  ///< sum m_i c_i, root frame
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();  ///< about the root origin, root frame
  std::vector<CollisionPart> parts;
  std::vector<std::pair<std::string, Eigen::Isometry3d>> links;  ///< root_T_link
  Eigen::Isometry3d root_T_frame = Eigen::Isometry3d::Identity();  ///< Bullet frame: COM, principal axes
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();
};

Eigen::Isometry3d toEigen(const urdf::Pose& pose)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z));
  t.rotate(Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z));
  return t;
}

btVector3 toBullet(const Eigen::Vector3d& v)
{
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}

btQuaternion toBullet(const Eigen::Quaterniond& q)
{
  return btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w()));
}

btTransform toBullet(const Eigen::Isometry3d& t)
{
  return btTransform(toBullet(Eigen::Quaterniond(t.rotation())), toBullet(Eigen::Vector3d(t.translation())));
}

Eigen::Vector3d toEigen(const btVector3& v)
{
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

bool isMovable(const urdf::Joint& joint)
{
  return joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS ||
         joint.type == urdf::Joint::PRISMATIC;
}

void addLink(const urdf::ModelInterface& model, const urdf::LinkConstSharedPtr& link, int body,
             const Eigen::Isometry3d& root_T_link, std::vector<MergedBody>& bodies)
{
  MergedBody& b = bodies[body];
  b.links.emplace_back(link->name, root_T_link);
  if (link->inertial && link->inertial->mass > 0.0)
  {
    const urdf::Inertial& in = *link->inertial;
    const Eigen::Isometry3d root_T_com = root_T_link * toEigen(in.origin);
    Eigen::Matrix3d local;
    local << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    const Eigen::Matrix3d r = root_T_com.rotation();
    const Eigen::Vector3d c = root_T_com.translation();
    b.mass += in.mass;
    b.mass_moment += in.mass * c;
    b.inertia_origin += r * local * r.transpose() + in.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  }
  for (const auto& collision : link->collision_array)
    if (collision && collision->geometry)
      b.parts.push_back({ root_T_link * toEigen(collision->origin), collision->geometry, link->name });
  for (const auto& joint : link->child_joints)
  {
    const urdf::LinkConstSharedPtr child = model.getLink(joint->child_link_name);
    if (!child)
      throw std::runtime_error("joint " + joint->name + ": child link '" + joint->child_link_name + "' missing");
    const Eigen::Isometry3d origin = root_T_link * toEigen(joint->parent_to_joint_origin_transform);
    if (!isMovable(*joint))
    {
      if (joint->type != urdf::Joint::FIXED)
        throw std::runtime_error("joint " + joint->name + ": type not supported (fixed, revolute, continuous, prismatic)");
      addLink(model, child, body, origin, bodies);
      continue;
    }
    MergedBody next;
    next.parent = body;
    next.joint = joint;
    next.parent_T_joint = origin;
    bodies.push_back(next);
    addLink(model, child, int(bodies.size()) - 1, Eigen::Isometry3d::Identity(), bodies);
  }
}

void computeFrame(MergedBody& b, const std::string& robot)
{
  if (b.mass <= 0.0)
  {
    b.mass = 1e-3;
    b.inertia_origin = 1e-7 * Eigen::Matrix3d::Identity();
    if (b.joint)
      b.mass_moment.setZero();
  }
  const Eigen::Vector3d com = b.mass_moment / b.mass;
  const Eigen::Matrix3d inertia =
      b.inertia_origin - b.mass * (com.squaredNorm() * Eigen::Matrix3d::Identity() - com * com.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (inertia + inertia.transpose()));
  Eigen::Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0)
    axes.col(2) = -axes.col(2);
  b.principal = eig.eigenvalues().cwiseMax(1e-9);
  b.root_T_frame = Eigen::Isometry3d::Identity();
  b.root_T_frame.translate(com);
  b.root_T_frame.rotate(axes);
  if (!b.principal.allFinite())
    throw std::runtime_error("robot " + robot + ": link " + b.links.front().first + ": inertia is not finite");
}

std::unique_ptr<btCollisionShape> makeShape(const urdf::Geometry& geometry, const std::string& link)
{
  switch (geometry.type)
  {
    case urdf::Geometry::BOX:
    {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      auto shape = std::make_unique<btBoxShape>(btVector3(btScalar(box.dim.x / 2), btScalar(box.dim.y / 2),
                                                          btScalar(box.dim.z / 2)));
      shape->setMargin(btScalar(0.001));
      return shape;
    }
    case urdf::Geometry::CYLINDER:
    {
      const auto& cyl = static_cast<const urdf::Cylinder&>(geometry);
      auto shape = std::make_unique<btCylinderShapeZ>(
          btVector3(btScalar(cyl.radius), btScalar(cyl.radius), btScalar(cyl.length / 2)));
      shape->setMargin(btScalar(0.001));
      return shape;
    }
    case urdf::Geometry::SPHERE:
      return std::make_unique<btSphereShape>(btScalar(static_cast<const urdf::Sphere&>(geometry).radius));
    case urdf::Geometry::MESH:
    {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      try
      {
        return loadConvexHull(resolveMeshPath(mesh.filename), Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z));
      }
      catch (const std::runtime_error& e)
      {
        throw std::runtime_error("link " + link + ": collision mesh: " + e.what());
      }
    }
  }
  throw std::runtime_error("link " + link + ": unknown collision geometry");
}

Eigen::Isometry3d worldPose(const urdf::ModelInterface& model, const std::string& link)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  urdf::LinkConstSharedPtr current = model.getLink(link);
  while (current && current->parent_joint)
  {
    pose = toEigen(current->parent_joint->parent_to_joint_origin_transform) * pose;
    current = model.getLink(current->parent_joint->parent_link_name);
  }
  return pose;
}
}  // namespace

ArticulatedRobot::ArticulatedRobot(const urdf::ModelInterface& model, const std::string& name,
                                   const std::string& base_link, const LinkMaterial& material)
  : name_(name)
{
  const urdf::LinkConstSharedPtr base = model.getLink(base_link);
  if (!base)
    throw std::runtime_error("robot " + name + ": base link '" + base_link + "' not in the URDF");
  std::vector<MergedBody> bodies(1);
  addLink(model, base, 0, Eigen::Isometry3d::Identity(), bodies);
  for (MergedBody& b : bodies)
    computeFrame(b, name);

  const int n_links = int(bodies.size()) - 1;
  const MergedBody& root = bodies[0];
  body_ = std::make_unique<btMultiBody>(n_links, btScalar(root.mass), toBullet(root.principal), true, false);
  body_->setBaseWorldTransform(toBullet(worldPose(model, base_link) * root.root_T_frame));

  for (int i = 1; i <= n_links; ++i)
  {
    const MergedBody& b = bodies[i];
    const MergedBody& p = bodies[b.parent];
    const urdf::Joint& joint = *b.joint;
    const Eigen::Matrix3d parent_R_this = p.root_T_frame.rotation().transpose() * b.parent_T_joint.rotation() *
                                          b.root_T_frame.rotation();
    const btQuaternion rot_parent_to_this = toBullet(Eigen::Quaterniond(parent_R_this.transpose()));
    const Eigen::Vector3d axis_urdf(joint.axis.x, joint.axis.y, joint.axis.z);
    const btVector3 axis = toBullet(Eigen::Vector3d(b.root_T_frame.rotation().transpose() * axis_urdf.normalized()));
    const btVector3 parent_com_to_pivot = toBullet(Eigen::Vector3d(
        p.root_T_frame.rotation().transpose() * (b.parent_T_joint.translation() - p.root_T_frame.translation())));
    const btVector3 pivot_to_com =
        toBullet(Eigen::Vector3d(b.root_T_frame.rotation().transpose() * b.root_T_frame.translation()));
    const int parent_link = b.parent - 1;
    if (joint.type == urdf::Joint::PRISMATIC)
      body_->setupPrismatic(i - 1, btScalar(b.mass), toBullet(b.principal), parent_link, rot_parent_to_this, axis,
                            parent_com_to_pivot, pivot_to_com, true);
    else
      body_->setupRevolute(i - 1, btScalar(b.mass), toBullet(b.principal), parent_link, rot_parent_to_this, axis,
                           parent_com_to_pivot, pivot_to_com, true);

    SimJoint sim;
    sim.name = joint.name;
    sim.link = i - 1;
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
  if (joints_.size() > std::size_t(kMaxJoints))
    throw std::runtime_error("robot " + name + ": " + std::to_string(joints_.size()) + " movable joints, at most " +
                             std::to_string(kMaxJoints) + " supported");
  body_->finalizeMultiDof();
  body_->setLinearDamping(0);
  body_->setAngularDamping(0);
  body_->setHasSelfCollision(false);
  body_->setCanSleep(false);

  for (int i = 0; i <= n_links; ++i)
  {
    const MergedBody& b = bodies[i];
    const Eigen::Isometry3d frame_T_root = b.root_T_frame.inverse();
    for (const auto& link : b.links)
      links_[link.first] = { i - 1, frame_T_root * link.second };
    auto compound = std::make_unique<btCompoundShape>(true, int(b.parts.size()));
    for (const CollisionPart& part : b.parts)
    {
      shapes_.push_back(makeShape(*part.geometry, part.link));
      compound->addChildShape(toBullet(frame_T_root * part.pose), shapes_.back().get());
    }
    if (b.parts.empty())
      compound->addChildShape(btTransform::getIdentity(), (shapes_.emplace_back(new btSphereShape(btScalar(0.001)))).get());
    auto collider = std::make_unique<btMultiBodyLinkCollider>(body_.get(), i - 1);
    collider->setCollisionShape(compound.get());
    collider->setFriction(btScalar(material.friction));
    collider->setRestitution(btScalar(material.restitution));
    collider->setUserIndex(b.parts.empty() ? 0 : 1);
    // Friction anchors: static friction corrects position drift, so a held object does not creep.
    collider->setCollisionFlags(collider->getCollisionFlags() | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    shapes_.push_back(std::move(compound));
    if (i == 0)
      body_->setBaseCollider(collider.get());
    else
      body_->getLink(i - 1).m_collider = collider.get();
    colliders_.push_back(std::move(collider));
  }

  response_.joint_of_dof.assign(std::size_t(body_->getNumDofs()), -1);
  for (std::size_t j = 0; j < joints_.size(); ++j)
    response_.joint_of_dof[std::size_t(body_->getLink(joints_[j].link).m_dofOffset)] = int(j);
  coupling_of_joint_.assign(joints_.size(), -1);
  std::vector<JointRange> ranges;
  for (SimJoint& sim : joints_)
  {
    const urdf::JointConstSharedPtr joint = model.getJoint(sim.name);
    if (sim.limited)
      ranges.push_back({ sim.link, sim.lower, sim.upper });
    if (joint->mimic)
    {
      const int master = jointIndex(joint->mimic->joint_name);
      if (master < 0)
        throw std::runtime_error("joint " + sim.name + ": mimics '" + joint->mimic->joint_name +
                                 "', not a movable joint of robot " + name);
      auto coupling = std::make_unique<JointCoupling>(body_.get(), sim.link, joints_[std::size_t(master)].link,
                                                      joint->mimic->multiplier, joint->mimic->offset, &response_);
      coupling->setGains(1e7, 1e4);
      sim.mimic = master;
      sim.multiplier = joint->mimic->multiplier;
      sim.offset = joint->mimic->offset;
      coupling_of_joint_[std::size_t(&sim - joints_.data())] = int(couplings_.size());
      couplings_.push_back(std::move(coupling));
      sim.mimic_drive = int(mimic_drives_.size());
      mimic_drives_.push_back(std::make_unique<JointDrive>(body_.get(), sim.link, &response_));
      continue;
    }
    sim.drive = int(drives_.size());
    drives_.push_back(std::make_unique<JointDrive>(body_.get(), sim.link, &response_));
    if (sim.max_effort > 0.0)
      drives_.back()->setForceLimit(sim.max_effort);
  }
  if (!ranges.empty())
    limits_ = std::make_unique<JointLimits>(body_.get(), ranges, &response_);
  feed_forward_.assign(joints_.size(), 0.0);
  setState(std::vector<double>(joints_.size(), 0.0), std::vector<double>(joints_.size(), 0.0));
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

int ArticulatedRobot::jointIndex(const std::string& joint) const
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == joint)
      return int(i);
  return -1;
}

std::vector<double> ArticulatedRobot::positions() const
{
  std::vector<double> q;
  q.reserve(joints_.size());
  for (const SimJoint& j : joints_)
    q.push_back(body_->getJointPos(j.link));
  return q;
}

std::vector<double> ArticulatedRobot::velocities() const
{
  std::vector<double> v;
  v.reserve(joints_.size());
  for (const SimJoint& j : joints_)
    v.push_back(body_->getJointVel(j.link));
  return v;
}

std::vector<double> ArticulatedRobot::efforts(double dt) const
{
  std::vector<double> e(joints_.size(), 0.0);
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    if (joints_[i].drive >= 0 && drive_constraints_)
      e[i] = drives_[std::size_t(joints_[i].drive)]->getAppliedImpulse(0) / dt;
    else if (coupling_of_joint_[i] >= 0)
    {
      e[i] = couplings_[std::size_t(coupling_of_joint_[i])]->getAppliedImpulse(0) / dt;
      if (drive_constraints_)
        e[i] += mimic_drives_[std::size_t(joints_[i].mimic_drive)]->getAppliedImpulse(0) / dt;
    }
    e[i] += feed_forward_[i];
  }
  return e;
}

void ArticulatedRobot::followMasters()
{
  for (const SimJoint& joint : joints_)
  {
    if (joint.mimic_drive < 0)
      continue;
    double factor = joint.multiplier, offset = joint.offset;
    const SimJoint* master = &joints_[std::size_t(joint.mimic)];
    while (master->mimic >= 0)
    {
      offset += factor * master->offset;
      factor *= master->multiplier;
      master = &joints_[std::size_t(master->mimic)];
    }
    const JointDrive& lead = *drives_[std::size_t(master->drive)];
    JointDrive& follower = *mimic_drives_[std::size_t(joint.mimic_drive)];
    follower.setGains(lead.stiffness(), lead.damping());
    follower.setForceLimit(joint.max_effort > 0.0 ? joint.max_effort : lead.forceLimit());
    follower.setTarget(factor * lead.targetPosition() + offset, factor * lead.targetVelocity());
  }
}

std::vector<double> ArticulatedRobot::withMimics(std::vector<double> positions) const
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].mimic >= 0)
      positions[i] = joints_[i].multiplier * positions[std::size_t(joints_[i].mimic)] + joints_[i].offset;
  return positions;
}

void ArticulatedRobot::setState(const std::vector<double>& positions, const std::vector<double>& velocities)
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    body_->setJointPos(joints_[i].link, btScalar(positions[i]));
    body_->setJointVel(joints_[i].link, btScalar(velocities[i]));
  }
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> origins;
  body_->forwardKinematics(rotations, origins);
  body_->updateCollisionObjectWorldTransforms(rotations, origins);
  response_.invalidate();
  refreshFrames();
}

void ArticulatedRobot::refreshFrames()
{
  poses_.resize(colliders_.size());
  for (std::size_t i = 0; i < colliders_.size(); ++i)
  {
    const btTransform& t = colliders_[i]->getWorldTransform();
    Eigen::Isometry3d& pose = poses_[i];
    pose.setIdentity();
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
        pose.matrix()(r, c) = t.getBasis()[r][c];
      pose.matrix()(r, 3) = t.getOrigin()[r];
    }
  }
}

const JointMatrix& ArticulatedRobot::updateDynamics()
{
  inertia_ = jointSpaceInertia(*this);
  response_.setInertia(inertia_);
  return inertia_;
}

const ArticulatedRobot::LinkFrame& ArticulatedRobot::linkFrame(const std::string& link) const
{
  const auto it = links_.find(link);
  if (it == links_.end())
    throw std::runtime_error("robot " + name_ + ": unknown link '" + link + "'");
  return it->second;
}

Eigen::Isometry3d ArticulatedRobot::linkPose(const std::string& link) const
{
  const LinkFrame& frame = linkFrame(link);
  return bodyPose(frame.body) * frame.body_T_link;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> ArticulatedRobot::bodyVelocity(int body) const
{
  const int n = body_->getNumLinks();
  std::vector<btVector3> omega(std::size_t(n + 1)), vel(std::size_t(n + 1));
  body_->compTreeLinkVelocities(omega.data(), vel.data());
  const Eigen::Matrix3d r = bodyPose(body).rotation();
  return { r * toEigen(omega[std::size_t(body + 1)]), r * toEigen(vel[std::size_t(body + 1)]) };
}

Eigen::Vector3d ArticulatedRobot::pointVelocity(const std::string& link, const Eigen::Vector3d& point) const
{
  const LinkFrame& frame = linkFrame(link);
  const auto velocity = bodyVelocity(frame.body);
  const Eigen::Vector3d arm = linkPose(link) * point - bodyPose(frame.body).translation();
  return velocity.second + velocity.first.cross(arm);
}

Eigen::Vector3d ArticulatedRobot::angularVelocity(const std::string& link) const
{
  return bodyVelocity(linkFrame(link).body).first;
}

void ArticulatedRobot::applyWrench(const std::string& link, const Eigen::Vector3d& point, const Eigen::Vector3d& force,
                                   const Eigen::Vector3d& torque)
{
  const LinkFrame& frame = linkFrame(link);
  if (frame.body < 0)
    return;
  const Eigen::Vector3d arm = linkPose(link) * point - bodyPose(frame.body).translation();
  body_->addLinkForce(frame.body, toBullet(force));
  body_->addLinkTorque(frame.body, toBullet(Eigen::Vector3d(arm.cross(force) + torque)));
}

void ArticulatedRobot::addJointTorque(std::size_t joint, double torque)
{
  feed_forward_[joint] += torque;
  body_->addJointTorque(joints_[joint].link, btScalar(torque));
}

void ArticulatedRobot::clearFeedForward()
{
  std::fill(feed_forward_.begin(), feed_forward_.end(), 0.0);
}

std::vector<double> ArticulatedRobot::gravityTorques(const Eigen::Vector3d& gravity) const
{
  const int n = body_->getNumLinks();
  double mass[kMaxJoints];  // one Bullet link per movable joint: at most kMaxJoints
  Eigen::Vector3d moment[kMaxJoints];
  for (int k = 0; k < n; ++k)
  {
    mass[std::size_t(k)] = body_->getLinkMass(k);
    moment[std::size_t(k)] = mass[std::size_t(k)] * bodyPose(k).translation();
  }
  for (int k = n - 1; k >= 0; --k)
  {
    const int parent = body_->getParent(k);
    if (parent >= 0)
    {
      mass[std::size_t(parent)] += mass[std::size_t(k)];
      moment[std::size_t(parent)] += moment[std::size_t(k)];
    }
  }
  std::vector<double> torques(joints_.size(), 0.0);
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    const std::size_t k = std::size_t(joints_[i].link);
    const btMultibodyLink& link = body_->getLink(int(k));
    const Eigen::Isometry3d& frame = bodyPose(int(k));
    if (joints_[i].prismatic)
      torques[i] = (frame.rotation() * toEigen(link.getAxisBottom(0))).dot(mass[k] * gravity);
    else
    {
      const Eigen::Vector3d axis = frame.rotation() * toEigen(link.getAxisTop(0));
      const Eigen::Vector3d pivot = frame * (-toEigen(link.m_dVector));
      torques[i] = axis.cross(moment[k] - mass[k] * pivot).dot(gravity);
    }
  }
  return torques;
}
}  // namespace vrrw_physics
