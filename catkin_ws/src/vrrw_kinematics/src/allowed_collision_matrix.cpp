#include "vrrw_kinematics/allowed_collision_matrix.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include "vrrw_kinematics/collision_world.h"
#include "world_box.h"

namespace vrrw_kinematics
{
namespace
{
std::uint64_t fnv1a(const std::string& text, std::uint64_t hash = 1469598103934665603ull)
{
  for (const unsigned char c : text)
  {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string describe(const Eigen::Isometry3d& pose)
{
  std::ostringstream out;
  out.precision(12);
  out << pose.matrix().reshaped().transpose();
  return out.str();
}

std::string describe(const vrrw_scene::Shape& shape)
{
  std::ostringstream out;
  out.precision(12);
  out << static_cast<int>(shape.type) << " " << shape.box_size.transpose() << " " << shape.radius << " "
      << shape.length << " " << shape.mesh_path << " " << describe(shape.origin);
  return out.str();
}

/// Pairs more than two joint variables apart whose boxes came this close in some sample are not allowed
/// as "never in collision": the samples cover their relative motion too sparsely to trust a near miss.
constexpr double kNearMargin = 0.02;

/// Allows each link's body with the nearest link up its chain that has a body (links without collision
/// geometry are passed over).
void allowAdjacentLinks(const CollisionWorld& world, AllowedCollisionMatrix& acm)
{
  const auto& bodies = world.bodies();
  const auto& links = world.model().links();
  std::vector<int> link_body(links.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!bodies[b].object)
      link_body[bodies[b].link] = static_cast<int>(b);
  for (std::size_t b = 0; b < bodies.size(); ++b)
  {
    if (bodies[b].object)
      continue;
    for (int l = links[bodies[b].link].parent_link; l >= 0; l = links[l].parent_link)
      if (link_body[l] >= 0)
      {
        acm.allow(bodies[b].name, bodies[link_body[l]].name, "adjacent");
        break;
      }
  }
}

/// Per candidate body pair: in how many of the uniform random states it collided, and whether its
/// boxes ever came within kNearMargin.
struct PairSamples
{
  std::vector<int> hits;
  std::vector<bool> near;
};

PairSamples samplePairs(const CollisionWorld& world, const std::vector<std::pair<int, int>>& candidates, int samples,
                        std::uint64_t seed)
{
  const RobotModel& model = world.model();
  const auto& bodies = world.bodies();
  const auto& elements = world.elements();
  PairSamples result{ std::vector<int>(candidates.size(), 0), std::vector<bool>(candidates.size(), false) };
  std::mt19937_64 rng(seed);
  Eigen::VectorXd variables(model.variableCount());
  std::vector<Eigen::Isometry3d> body_poses;
  std::vector<Eigen::Isometry3d> element_poses(elements.size());
  std::vector<Eigen::Vector3d> centers(elements.size()), halves(elements.size());
  for (int s = 0; s < samples; ++s)
  {
    for (std::size_t v = 0; v < model.variableCount(); ++v)
    {
      const JointModel& joint = model.joints()[model.variableJoints()[v]];
      variables[v] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
    }
    world.bodyTransforms(variables, body_poses);
    for (std::size_t e = 0; e < elements.size(); ++e)
    {
      element_poses[e] = body_poses[elements[e].body] * elements[e].local;
      elementAabb(elements[e], element_poses[e], centers[e], halves[e]);
    }
    for (std::size_t c = 0; c < candidates.size(); ++c)
    {
      bool collide = false;
      for (const int ea : bodies[candidates[c].first].elements)
        for (const int eb : bodies[candidates[c].second].elements)
        {
          const Eigen::Vector3d margin = Eigen::Vector3d::Constant(kNearMargin);
          if (!aabbOverlap(centers[ea], halves[ea] + margin, centers[eb], halves[eb] + margin))
            continue;
          result.near[c] = true;
          if (!collide && aabbOverlap(centers[ea], halves[ea], centers[eb], halves[eb]))
            collide = elementsCollide(elements[ea], element_poses[ea], elements[eb], element_poses[eb]);
        }
      result.hits[c] += collide ? 1 : 0;
    }
  }
  return result;
}

/// Number of joint variables (mimic joints count as their leader) between links a and b.
std::size_t variablesBetween(const RobotModel& model, int a, int b)
{
  std::vector<int> variables;
  const auto climb = [&](int from, int to) {
    for (int l = from; l != to && l > 0; l = model.links()[l].parent_link)
    {
      const JointModel& joint = model.joints()[model.links()[l].parent_joint];
      const int v = joint.variable >= 0 ? joint.variable : joint.mimic_variable;
      if (v >= 0 && std::find(variables.begin(), variables.end(), v) == variables.end())
        variables.push_back(v);
    }
  };
  int common = a;
  while (common > 0 && !model.isDescendant(b, common))
    common = model.links()[common].parent_link;
  climb(a, common);
  climb(b, common);
  return variables.size();
}

}  // namespace

std::pair<std::string, std::string> AllowedCollisionMatrix::ordered(const std::string& a, const std::string& b)
{
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

void AllowedCollisionMatrix::allow(const std::string& a, const std::string& b, const std::string& reason)
{
  entries_[ordered(a, b)] = reason;
}

void AllowedCollisionMatrix::forbid(const std::string& a, const std::string& b)
{
  entries_.erase(ordered(a, b));
}

bool AllowedCollisionMatrix::allowed(const std::string& a, const std::string& b) const
{
  return entries_.count(ordered(a, b)) > 0;
}

std::string AllowedCollisionMatrix::reason(const std::string& a, const std::string& b) const
{
  const auto it = entries_.find(ordered(a, b));
  return it == entries_.end() ? "" : it->second;
}

std::size_t AllowedCollisionMatrix::count(const std::string& reason) const
{
  std::size_t n = 0;
  for (const auto& entry : entries_)
    n += entry.second == reason ? 1 : 0;
  return n;
}

void AllowedCollisionMatrix::save(const std::string& path, const std::string& key) const
{
  // a name of its own: the nodes of one bring-up may all compute and save the same matrix at once
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary);
    if (!out)
      return;
    out << "# " << key << "\n";
    for (const auto& entry : entries_)
      out << entry.first.first << " " << entry.first.second << " " << entry.second << "\n";
  }
  std::rename(temporary.c_str(), path.c_str());
}

bool AllowedCollisionMatrix::load(const std::string& path, const std::string& key)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line != "# " + key)
    return false;
  entries_.clear();
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string a, b, reason;
    if (fields >> a >> b >> reason)
      allow(a, b, reason);
  }
  return true;
}

// CollisionWorld's own matrix: computed from random samples of its model, cached by content.

std::string CollisionWorld::contentKey(int samples, std::uint64_t seed) const
{
  std::uint64_t hash = fnv1a(urdf_);
  for (const CollisionBody& body : bodies_)
  {
    hash = fnv1a(body.name + " " + std::to_string(body.link) + " " + describe(body.offset), hash);
    for (const int e : body.elements)
    {
      vrrw_scene::Shape shape;
      shape.type = elements_[e].type;
      shape.box_size = 2.0 * elements_[e].half_extents;
      shape.radius = elements_[e].bounding_radius;
      shape.origin = elements_[e].local;
      hash = fnv1a(describe(shape), hash);
    }
  }
  hash = fnv1a(std::to_string(samples) + " " + std::to_string(seed) + " acm-v3", hash);
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

void CollisionWorld::computeAllowedCollisions(int samples, std::uint64_t seed)
{
  AllowedCollisionMatrix acm;
  for (const auto& entry : acm_.entries())
    if (entry.second == "attached" || entry.second == "user")
      acm.allow(entry.first.first, entry.first.second, entry.second);
  allowAdjacentLinks(*this, acm);
  std::vector<std::pair<int, int>> candidates;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    for (std::size_t j = i + 1; j < bodies_.size(); ++j)
      if (!acm.allowed(bodies_[i].name, bodies_[j].name))
        candidates.emplace_back(static_cast<int>(i), static_cast<int>(j));
  const PairSamples sampled = samplePairs(*this, candidates, samples, seed);
  for (std::size_t c = 0; c < candidates.size(); ++c)
  {
    const CollisionBody& a = bodies_[candidates[c].first];
    const CollisionBody& b = bodies_[candidates[c].second];
    const bool same_robot = !a.robot.empty() && a.robot == b.robot;
    if (sampled.hits[c] == samples && samples > 0 && (same_robot || (fixedInWorld(a) && fixedInWorld(b))))
      acm.allow(a.name, b.name, "always");
    else if (samples > 0 && same_robot && sampled.hits[c] == 0 &&
             (!sampled.near[c] || variablesBetween(model_, a.link, b.link) <= 2))
      acm.allow(a.name, b.name, "never");
  }
  acm_ = acm;
  rebuildPairs();
}

bool CollisionWorld::loadOrComputeAllowedCollisions(const std::string& cache_dir, int samples, std::uint64_t seed)
{
  const std::string key = contentKey(samples, seed);
  const std::string path = cache_dir + "/acm_" + key + ".txt";
  AllowedCollisionMatrix cached;
  if (!cache_dir.empty() && cached.load(path, key))
  {
    acm_ = cached;
    rebuildPairs();
    return true;
  }
  computeAllowedCollisions(samples, seed);
  if (!cache_dir.empty())
  {
    ::mkdir(cache_dir.c_str(), 0755);
    acm_.save(path, key);
  }
  return false;
}

}  // namespace vrrw_kinematics
