#include "vrrw_kinematics/state_checker.h"

#include <algorithm>
#include <limits>
#include <map>

#include "vrrw_kinematics/kinematics_error.h"
#include "world_box.h"

namespace vrrw_kinematics
{
namespace
{
bool sphereTouchesBox(const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& box_center,
                      const Eigen::Vector3d& box_half)
{
  const Eigen::Vector3d outside = ((center - box_center).cwiseAbs() - box_half).cwiseMax(0.0);
  return outside.squaredNorm() <= radius * radius;
}
}  // namespace

StateChecker::StateChecker(const CollisionWorld& world, const std::vector<std::string>& joints,
                           const Eigen::VectorXd& variables)
  : world_(world)
{
  const RobotModel& model = world.model();
  if (static_cast<std::size_t>(variables.size()) != model.variableCount())
    throw KinematicsError(ErrorCode::InvalidArgument, "state: expected " + std::to_string(model.variableCount()) +
                                                          " joint values, got " + std::to_string(variables.size()));
  readGroup(joints);
  std::vector<Eigen::Isometry3d> link_poses;
  model.linkTransforms(variables, link_poses);
  const std::vector<int> anchor_of = anchorLinks(link_poses);
  std::vector<int> slot_of, moving_body_of;
  placeBodies(link_poses, anchor_of, slot_of, moving_body_of);
  boundStaticBodies();
  groupCheckedPairs(slot_of, moving_body_of);

  anchor_poses_.resize(anchors_.size());
  sphere_centers_.resize(moving_bodies_.size());
  element_poses_.resize(moving_elements_.size());
  centers_.resize(moving_elements_.size());
  halves_.resize(moving_elements_.size());
  stamps_.assign(moving_elements_.size(), 0);
  computeReach();
}

void StateChecker::readGroup(const std::vector<std::string>& joints)
{
  const RobotModel& model = world_.model();
  for (const std::string& name : joints)
  {
    const int j = model.jointIndex(name);
    if (model.joints()[j].variable < 0)
      throw KinematicsError(ErrorCode::InvalidArgument, "joint " + name + ": fixed or mimic, cannot be planned");
    group_.push_back(j);
    joint_names_.push_back(name);
  }
}

std::vector<int> StateChecker::anchorLinks(const std::vector<Eigen::Isometry3d>& link_poses)
{
  // anchor_of[l]: the group joint whose child frame link l hangs from rigidly, -1 when it does not move.
  const RobotModel& model = world_.model();
  std::vector<int> anchor_of(model.links().size(), -1);
  for (std::size_t l = 1; l < model.links().size(); ++l)
  {
    const LinkModel& link = model.links()[l];
    const auto it = std::find(group_.begin(), group_.end(), link.parent_joint);
    if (it == group_.end())
    {
      anchor_of[l] = anchor_of[link.parent_link];
      continue;
    }
    Anchor anchor;
    anchor.joint = *it;
    anchor.group_index = static_cast<int>(it - group_.begin());
    anchor.parent = anchor_of[link.parent_link];
    const Eigen::Isometry3d parent_pose =
        anchor.parent >= 0 ? link_poses[model.joints()[anchors_[anchor.parent].joint].child_link]
                           : Eigen::Isometry3d::Identity();
    anchor.before = parent_pose.inverse() * link_poses[link.parent_link] * model.joints()[*it].origin;
    anchor_of[l] = static_cast<int>(anchors_.size());
    anchors_.push_back(anchor);
  }
  return anchor_of;
}

void StateChecker::placeBodies(const std::vector<Eigen::Isometry3d>& link_poses, const std::vector<int>& anchor_of,
                               std::vector<int>& slot_of, std::vector<int>& moving_body_of)
{
  const RobotModel& model = world_.model();
  std::vector<Eigen::Isometry3d> anchor_at_start(anchors_.size());
  for (std::size_t a = 0; a < anchors_.size(); ++a)
    anchor_at_start[a] = link_poses[model.joints()[anchors_[a].joint].child_link];
  const auto& elements = world_.elements();
  const auto& bodies = world_.bodies();
  static_poses_.resize(elements.size());
  static_centers_.resize(elements.size());
  static_halves_.resize(elements.size());
  slot_of.assign(elements.size(), -1);
  moving_body_of.assign(bodies.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b)
  {
    const CollisionBody& body = bodies[b];
    const Eigen::Isometry3d body_pose = body.link >= 0 ? link_poses[body.link] * body.offset : body.offset;
    const int anchor = body.link >= 0 ? anchor_of[body.link] : -1;
    for (const int e : body.elements)
    {
      static_poses_[e] = body_pose * elements[e].local;
      elementAabb(elements[e], static_poses_[e], static_centers_[e], static_halves_[e]);
      if (anchor < 0)
        continue;
      slot_of[e] = static_cast<int>(moving_elements_.size());
      moving_elements_.push_back(MovingElement{ e, anchor, anchor_at_start[anchor].inverse() * static_poses_[e] });
    }
    if (anchor < 0 || body.elements.empty())
      continue;
    MovingBody moving_body{ static_cast<int>(b), anchor, Eigen::Vector3d::Zero(), 0.0 };
    for (const int e : body.elements)
      moving_body.center += moving_elements_[slot_of[e]].offset.translation() / static_cast<double>(body.elements.size());
    for (const int e : body.elements)
      moving_body.radius = std::max(moving_body.radius, (moving_elements_[slot_of[e]].offset.translation() -
                                                         moving_body.center).norm() + elements[e].bounding_radius);
    moving_body_of[b] = static_cast<int>(moving_bodies_.size());
    moving_bodies_.push_back(moving_body);
  }
}

void StateChecker::boundStaticBodies()
{
  const auto& bodies = world_.bodies();
  body_centers_.resize(bodies.size());
  body_halves_.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b)
  {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (const int e : bodies[b].elements)
    {
      low = low.cwiseMin(static_centers_[e] - static_halves_[e]);
      high = high.cwiseMax(static_centers_[e] + static_halves_[e]);
    }
    body_centers_[b] = 0.5 * (low + high);
    body_halves_[b] = 0.5 * (high - low);
  }
}

void StateChecker::groupCheckedPairs(const std::vector<int>& slot_of, const std::vector<int>& moving_body_of)
{
  const auto& elements = world_.elements();
  const auto& bodies = world_.bodies();
  std::map<std::pair<int, int>, BodyPair> grouped;
  for (const auto& pair : world_.checkedPairs())
  {
    int first = pair.first, second = pair.second;
    if (slot_of[first] < 0)
      std::swap(first, second);
    if (slot_of[first] < 0)
      continue;
    const int body_a = moving_body_of[elements[first].body];
    const int body_b = elements[second].body;
    const bool moving = slot_of[second] >= 0;
    // Two elements on the same anchor never move relative to each other: decide them once, here.
    if (moving && moving_elements_[slot_of[first]].anchor == moving_elements_[slot_of[second]].anchor &&
        !elementsCollide(elements[first], static_poses_[first], elements[second], static_poses_[second]))
      continue;
    BodyPair& entry = grouped[{ body_a, moving ? moving_body_of[body_b] : -1 - body_b }];
    entry.a = body_a;
    entry.b = moving ? moving_body_of[body_b] : body_b;
    entry.moving = moving;
    entry.elements.emplace_back(slot_of[first], moving ? slot_of[second] : -1 - second);
    ++pair_count_;
  }
  static_pair_index_.assign(moving_bodies_.size() * bodies.size(), -1);
  std::vector<int> static_bodies;
  for (const auto& entry : grouped)
  {
    const BodyPair& pair = entry.second;
    if (pair.moving)
    {
      moving_pairs_.push_back(pair);
      continue;
    }
    static_pair_index_[static_cast<std::size_t>(pair.a) * bodies.size() + static_cast<std::size_t>(pair.b)] =
        static_cast<int>(static_pairs_.size());
    static_pairs_.push_back(pair);
    if (std::find(static_bodies.begin(), static_bodies.end(), pair.b) == static_bodies.end())
      static_bodies.push_back(pair.b);
  }
  tree_root_ = static_bodies.empty() ? -1 : buildTree(static_bodies, 0, static_bodies.size());
}

int StateChecker::buildTree(std::vector<int>& bodies, std::size_t begin, std::size_t end)
{
  BoxNode node;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (std::size_t i = begin; i < end; ++i)
  {
    low = low.cwiseMin(body_centers_[bodies[i]] - body_halves_[bodies[i]]);
    high = high.cwiseMax(body_centers_[bodies[i]] + body_halves_[bodies[i]]);
  }
  node.center = 0.5 * (low + high);
  node.half = 0.5 * (high - low);
  const int index = static_cast<int>(tree_.size());
  tree_.push_back(node);
  if (end - begin == 1)
  {
    tree_[index].body = bodies[begin];
    return index;
  }
  int axis = 0;
  node.half.maxCoeff(&axis);
  const std::size_t middle = (begin + end) / 2;
  std::nth_element(bodies.begin() + static_cast<std::ptrdiff_t>(begin), bodies.begin() + static_cast<std::ptrdiff_t>(middle),
                   bodies.begin() + static_cast<std::ptrdiff_t>(end),
                   [&](int a, int b) { return body_centers_[a][axis] < body_centers_[b][axis]; });
  const int left = buildTree(bodies, begin, middle);
  const int right = buildTree(bodies, middle, end);
  tree_[index].left = left;
  tree_[index].right = right;
  return index;
}

void StateChecker::computeReach()
{
  const RobotModel& model = world_.model();
  const auto& elements = world_.elements();
  const auto& bodies = world_.bodies();
  reach_.assign(group_.size(), 0.0);
  for (std::size_t g = 0; g < group_.size(); ++g)
  {
    const JointModel& joint = model.joints()[group_[g]];
    if (joint.type == JointModel::Type::Prismatic)
    {
      reach_[g] = 1.0;
      continue;
    }
    for (const MovingElement& moving : moving_elements_)
    {
      const CollisionBody& body = bodies[elements[moving.element].body];
      if (!model.isDescendant(body.link, joint.child_link))
        continue;
      double bound = (body.offset * elements[moving.element].local).translation().norm() +
                     elements[moving.element].bounding_radius;
      for (int l = body.link; l != joint.child_link; l = model.links()[l].parent_link)
      {
        const JointModel& above = model.joints()[model.links()[l].parent_joint];
        bound += above.origin.translation().norm();
        if (above.type == JointModel::Type::Prismatic)
          bound += std::max(std::abs(above.lower), std::abs(above.upper));
      }
      reach_[g] = std::max(reach_[g], bound);
    }
  }
}

const Eigen::Isometry3d& StateChecker::elementPose(int slot)
{
  if (stamps_[slot] != generation_)
  {
    const MovingElement& moving = moving_elements_[slot];
    element_poses_[slot] = anchor_poses_[moving.anchor] * moving.offset;
    elementAabb(world_.elements()[moving.element], element_poses_[slot], centers_[slot], halves_[slot]);
    stamps_[slot] = generation_;
  }
  return element_poses_[slot];
}

template <bool kReport>
bool StateChecker::collide(const Eigen::VectorXd& q, Contact* contact)
{
  const RobotModel& model = world_.model();
  ++generation_;
  for (std::size_t a = 0; a < anchors_.size(); ++a)
  {
    const Anchor& anchor = anchors_[a];
    const JointModel& joint = model.joints()[anchor.joint];
    Eigen::Isometry3d& pose = anchor_poses_[a];
    pose = anchor.parent >= 0 ? anchor_poses_[anchor.parent] * anchor.before : anchor.before;
    if (joint.type == JointModel::Type::Prismatic)
      pose.translation() += pose.linear() * (joint.axis * q[anchor.group_index]);
    else
      pose.linear() = pose.linear() * Eigen::AngleAxisd(q[anchor.group_index], joint.axis).toRotationMatrix();
  }
  for (std::size_t b = 0; b < moving_bodies_.size(); ++b)
    sphere_centers_[b] = anchor_poses_[moving_bodies_[b].anchor] * moving_bodies_[b].center;

  if (tree_root_ >= 0)
    for (std::size_t b = 0; b < moving_bodies_.size(); ++b)
      if (staticCollides<kReport>(static_cast<int>(b), tree_root_, contact))
        return true;
  for (const BodyPair& pair : moving_pairs_)
    if (pairCollides<kReport>(pair, contact))
      return true;
  return false;
}

template <bool kReport>
bool StateChecker::staticCollides(int moving_body, int node, Contact* contact)
{
  const BoxNode& box = tree_[node];
  if (!sphereTouchesBox(sphere_centers_[moving_body], moving_bodies_[moving_body].radius, box.center, box.half))
    return false;
  if (box.body >= 0)
  {
    const int pair = static_pair_index_[static_cast<std::size_t>(moving_body) * world_.bodies().size() +
                                        static_cast<std::size_t>(box.body)];
    return pair >= 0 && pairCollides<kReport>(static_pairs_[pair], contact);
  }
  return staticCollides<kReport>(moving_body, box.left, contact) ||
         staticCollides<kReport>(moving_body, box.right, contact);
}

template <bool kReport>
bool StateChecker::pairCollides(const BodyPair& pair, Contact* contact)
{
  const double radius = moving_bodies_[pair.a].radius;
  if (pair.moving)
  {
    const double reach = radius + moving_bodies_[pair.b].radius;
    if ((sphere_centers_[pair.a] - sphere_centers_[pair.b]).squaredNorm() > reach * reach)
      return false;
  }
  else if (!sphereTouchesBox(sphere_centers_[pair.a], radius, body_centers_[pair.b], body_halves_[pair.b]))
    return false;
  const auto& elements = world_.elements();
  for (const auto& element_pair : pair.elements)
  {
    const int slot_a = element_pair.first;
    const Eigen::Isometry3d& pose_a = elementPose(slot_a);
    const int slot_b = element_pair.second;
    const bool b_moves = slot_b >= 0;
    const int element_b = b_moves ? moving_elements_[slot_b].element : -1 - slot_b;
    const Eigen::Isometry3d& pose_b = b_moves ? elementPose(slot_b) : static_poses_[element_b];
    const Eigen::Vector3d& center_b = b_moves ? centers_[slot_b] : static_centers_[element_b];
    const Eigen::Vector3d& half_b = b_moves ? halves_[slot_b] : static_halves_[element_b];
    const int element_a = moving_elements_[slot_a].element;
    if (!aabbOverlap(centers_[slot_a], halves_[slot_a], center_b, half_b) ||
        !elementsCollide(elements[element_a], pose_a, elements[element_b], pose_b))
      continue;
    if (kReport)
    {
      contact->collision = true;
      contact->body_a = world_.bodies()[elements[element_a].body].name;
      contact->body_b = world_.bodies()[elements[element_b].body].name;
    }
    return true;
  }
  return false;
}

bool StateChecker::valid(const Eigen::VectorXd& q)
{
  return !collide<false>(q, nullptr);
}

Contact StateChecker::check(const Eigen::VectorXd& q)
{
  Contact contact;
  collide<true>(q, &contact);
  return contact;
}
}  // namespace vrrw_kinematics
