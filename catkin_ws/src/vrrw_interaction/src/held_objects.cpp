#include <vrrw_interaction/held_objects.h>

#include <algorithm>
#include <vrrw_interaction/grab_target.h>

namespace vrrw_interaction
{
bool fingersSqueeze(const std::string& object, const std::vector<BodyContact>& contacts,
                    const std::vector<std::string>& gripper_links, const Eigen::Vector3d& tcp)
{
  std::vector<Eigen::Vector3d> pads;  // where gripper links press on the object, from the TCP
  for (const BodyContact& c : contacts)
  {
    if (c.body_a != object && c.body_b != object)
      continue;
    const std::string& other = c.body_a == object ? c.body_b : c.body_a;
    if (c.normal_force >= kSqueezeForce && std::find(gripper_links.begin(), gripper_links.end(), other) != gripper_links.end())
      pads.push_back(c.position - tcp);
  }
  // opposite sides: two offsets from the TCP pointing away from each other (the fingers close towards it)
  for (std::size_t i = 0; i < pads.size(); ++i)
    for (std::size_t j = i + 1; j < pads.size(); ++j)
      if (pads[i].dot(pads[j]) < 0.0)
        return true;
  return false;
}

bool closedGripperHolds(const vrrw_kinematics::CollisionWorld& world, const Eigen::VectorXd& state,
                        const vrrw_scene::Robot& robot, const GripperRange& gripper, const std::string& object)
{
  // fake mode has no contact forces: a gripper closed well past open with its TCP at the object stands for a grasp
  const vrrw_kinematics::RobotModel& model = world.model();
  const int v = model.variableIndex(gripper.joint);
  if (v < 0 || gripper.closedFraction(state[v]) < kClosedFraction)
    return false;
  const Eigen::Vector3d tcp = model.relativeTransform(state, model.links()[0].name, robot.tcp_link).translation();
  return nearestBody(world, state, tcp, kTouchDistance, [&](const vrrw_kinematics::CollisionBody& body) {
           return body.name == object;
         }).has_value();
}

std::vector<std::string> linksBelow(const vrrw_kinematics::RobotModel& model, const std::string& link)
{
  std::vector<std::string> below;
  for (std::vector<int> open{ model.linkIndex(link) }; !open.empty();)  // depth first over the child links
  {
    const vrrw_kinematics::LinkModel& next = model.links()[open.back()];
    open.pop_back();
    below.push_back(next.name);
    open.insert(open.end(), next.child_links.begin(), next.child_links.end());
  }
  return below;
}

HeldObjects::HeldObjects(vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene)
  : world_(world), scene_(scene)
{
  for (const vrrw_scene::Robot& robot : scene.robots)
  {
    if (robot.gripper.empty())
      continue;
    grippers_[robot.name] = linksBelow(world.model(), robot.tool_link);
    if (const auto range = gripperRange(world.model(), robot))
      ranges_[robot.name] = *range;
  }
}

const std::vector<std::string>& HeldObjects::gripperLinks(const std::string& robot) const
{
  static const std::vector<std::string> none;
  const auto it = grippers_.find(robot);
  return it == grippers_.end() ? none : it->second;
}

std::string HeldObjects::squeezedBy(const std::string& object, const std::vector<BodyContact>& contacts,
                                    const Eigen::VectorXd& live) const
{
  const vrrw_kinematics::RobotModel& model = world_.model();
  std::string holder;
  for (const auto& [robot, links] : grippers_)
  {
    const Eigen::Vector3d tcp =
        model.relativeTransform(live, model.links()[0].name, scene_.robot(robot)->tcp_link).translation();
    if (fingersSqueeze(object, contacts, links, tcp))
      holder = robot;
  }
  return holder;
}

std::string HeldObjects::heldByClosedGripper(const std::string& object, const Eigen::VectorXd& live) const
{
  std::string holder;
  for (const auto& [robot, range] : ranges_)
    if (closedGripperHolds(world_, live, *scene_.robot(robot), range, object))
      holder = robot;
  return holder;
}

std::string HeldObjects::holder(const std::string& object) const
{
  const auto it = held_.find(object);
  return it == held_.end() ? "" : it->second.robot;
}

std::vector<HeldEvent> HeldObjects::update(const std::string& object, const std::string& holder,
                                           const Eigen::VectorXd& live, double now)
{
  const auto it = held_.find(object);
  if (!holder.empty() && it != held_.end())
  {
    if (it->second.robot == holder)
      it->second.last_seen = now;
    return {};  // (held by another robot: that one must let go first)
  }
  if (!holder.empty())
    return { attach(object, holder, live, now) };
  // nobody holds it by the rule now: a held object is let go only after kLetGo without it (a squeeze flickers as
  // the contacts settle, a message or two may miss a pad)
  if (it == held_.end() || now - it->second.last_seen < kLetGo)
    return {};
  return { detach(object, live) };
}

HeldEvent HeldObjects::attach(const std::string& object, const std::string& robot, const Eigen::VectorXd& live,
                              double now)
{
  const std::string& tcp = scene_.robot(robot)->tcp_link;
  Held held{ robot, {}, {}, Eigen::Vector3d::Zero(), now };
  world_.attachObject(object, tcp, live, grippers_[robot]);
  // a free object standing on the table is "always" touching it in the ACM: held, that pair is checked
  for (const vrrw_scene::Object& fixed : scene_.objects)
    if (fixed.fixed && world_.bodyIndex(fixed.name) >= 0 && world_.acm().allowed(object, fixed.name))
      held.restore.push_back(fixed.name), held.supports.push_back(fixed.name);
  // what it rests on may touch it until it is lifted: a plan starting at the grasp is not in collision
  // (a few rounds: it may stand on more than one thing)
  for (int k = 0; k < 4; ++k)
  {
    const vrrw_kinematics::DistanceReport d = world_.distance(live, object);
    const std::string& other = d.body_a == object ? d.body_b : d.body_a;
    const vrrw_scene::Object* support = scene_.object(other);
    if (d.distance > kRestDistance || !support || !support->fixed)
      break;
    world_.setAllowed(object, other, true);
    held.supports.push_back(other);
  }
  held.taken_at = position(object, live);
  std::string detail = object + " to " + tcp;
  for (const std::string& support : held.supports)
    detail += " (touching " + support + " until lifted 1 cm)";
  held_[object] = held;
  return { robot, "attach", detail };
}

HeldEvent HeldObjects::detach(const std::string& object, const Eigen::VectorXd& live)
{
  Held& held = held_.at(object);
  releaseSupports(object, held, live, true);
  world_.detachObject(object, live);  // where it is now
  // standing free again: the fixed objects the ACM let it touch before the grasp (the table it stands on)
  for (const std::string& fixed : held.restore)
    world_.setAllowed(object, fixed, true);
  const HeldEvent event{ held.robot, "detach", object + " from " + scene_.robot(held.robot)->tcp_link };
  held_.erase(object);
  return event;
}

void HeldObjects::releaseLifted(const Eigen::VectorXd& live)
{
  for (auto& [object, held] : held_)
    releaseSupports(object, held, live, false);
}

void HeldObjects::releaseSupports(const std::string& object, Held& held, const Eigen::VectorXd& live, bool all)
{
  // kLift (1 cm) from where it was taken: clear of the table, past the few millimetres a squeeze settles by
  if (held.supports.empty() || (!all && (position(object, live) - held.taken_at).norm() < kLift))
    return;
  for (const std::string& support : held.supports)
    world_.setAllowed(object, support, false);
  held.supports.clear();
}

Eigen::Vector3d HeldObjects::position(const std::string& object, const Eigen::VectorXd& live) const
{
  std::vector<Eigen::Isometry3d> bodies;
  world_.bodyTransforms(live, bodies);
  return bodies[world_.bodyIndex(object)].translation();
}

void HeldObjects::allowPlaceContact(const std::string& robot, const std::string& surface, bool allow)
{
  if (!allow)
  {
    for (const auto& [object, other] : place_contacts_)
      world_.setAllowed(object, other, false);
    place_contacts_.clear();
    return;
  }
  for (const auto& [object, held] : held_)
    if (held.robot == robot && object != surface && !world_.acm().allowed(object, surface))
    {
      world_.setAllowed(object, surface, true);
      place_contacts_.emplace_back(object, surface);
    }
}
}  // namespace vrrw_interaction
