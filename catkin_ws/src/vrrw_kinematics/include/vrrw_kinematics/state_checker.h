#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "vrrw_kinematics/collision_world.h"

namespace vrrw_kinematics
{
/// \brief Fast collision check of one joint group (an arm) against the rest of a CollisionWorld frozen at
/// a given state: only the links below the group move; only pairs with a moving body that the ACM does
/// not allow are tested, each behind an axis-aligned box prefilter. Not thread-safe (keeps scratch state).
class StateChecker
{
public:
  /// \brief `joints` are variables of world.model(); `variables` fixes every other joint.
  StateChecker(const CollisionWorld& world, const std::vector<std::string>& joints, const Eigen::VectorXd& variables);

  std::size_t size() const { return group_.size(); }
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  /// \brief True when the group at `q` touches nothing it may not touch.
  bool valid(const Eigen::VectorXd& q);
  /// \brief Like valid(), naming the first colliding pair.
  Contact check(const Eigen::VectorXd& q);
  /// \brief Upper bound on how far (m) any point of the moving bodies travels per unit motion of each joint
  /// (rad for revolute, m for prismatic); a move dq displaces no point more than sum_i reach_i |dq_i|.
  const std::vector<double>& reach() const { return reach_; }
  /// \brief Number of element pairs tested per state (after the ACM, before the box prefilters).
  std::size_t pairCount() const { return pair_count_; }

private:
  struct Anchor  ///< child frame of one group joint
  {
    int parent = -1;  ///< anchor above it; -1: fixed to the world
    int joint = -1;   ///< model joint index
    int group_index = -1;
    Eigen::Isometry3d before = Eigen::Isometry3d::Identity();  ///< parent anchor (or world) to the joint frame at zero
  };
  struct MovingElement
  {
    int element = -1;
    int anchor = -1;
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();  ///< anchor frame to element frame
  };
  struct MovingBody
  {
    int body = -1;
    int anchor = -1;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< bounding sphere centre in the anchor frame
    double radius = 0.0;
  };
  struct BodyPair
  {
    int a = -1;  ///< index into moving_bodies_
    int b = -1;  ///< index into moving_bodies_ (moving pair) or a world body index (static pair)
    bool moving = false;
    std::vector<std::pair<int, int>> elements;  ///< (moving element slot, element slot or -1 - static element)
  };
  /// \brief Construction stages: the group's joints; the anchor (moving frame) of every link; every body's
  /// elements placed at the frozen state, moving ones relative to their anchor; the static bodies' boxes;
  /// the checked pairs grouped per body pair, static ones behind a box tree.
  void readGroup(const std::vector<std::string>& joints);
  std::vector<int> anchorLinks(const std::vector<Eigen::Isometry3d>& link_poses);
  void placeBodies(const std::vector<Eigen::Isometry3d>& link_poses, const std::vector<int>& anchor_of,
                   std::vector<int>& slot_of, std::vector<int>& moving_body_of);
  void boundStaticBodies();
  void groupCheckedPairs(const std::vector<int>& slot_of, const std::vector<int>& moving_body_of);
  template <bool kReport>
  bool collide(const Eigen::VectorXd& q, Contact* contact);
  void computeReach();
  const Eigen::Isometry3d& elementPose(int slot);
  template <bool kReport>
  bool pairCollides(const BodyPair& pair, Contact* contact);

  const CollisionWorld& world_;
  std::vector<int> group_;  ///< model joint index per group joint
  std::vector<std::string> joint_names_;
  std::vector<Anchor> anchors_;
  std::vector<Eigen::Isometry3d> anchor_poses_;
  std::vector<MovingElement> moving_elements_;
  std::vector<MovingBody> moving_bodies_;
  std::vector<Eigen::Vector3d> sphere_centers_;
  std::vector<Eigen::Isometry3d> element_poses_;  ///< per moving element slot, valid when stamp matches
  std::vector<Eigen::Vector3d> centers_;
  std::vector<Eigen::Vector3d> halves_;
  std::vector<std::uint64_t> stamps_;
  std::uint64_t generation_ = 0;
  std::vector<Eigen::Isometry3d> static_poses_;  ///< per world element
  std::vector<Eigen::Vector3d> static_centers_;
  std::vector<Eigen::Vector3d> static_halves_;
  std::vector<Eigen::Vector3d> body_centers_;  ///< static bodies' boxes
  std::vector<Eigen::Vector3d> body_halves_;
  struct BoxNode  ///< bounding-box tree over the static bodies
  {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Vector3d half = Eigen::Vector3d::Zero();
    int left = -1;
    int right = -1;
    int body = -1;  ///< leaf: world body index
  };
  int buildTree(std::vector<int>& bodies, std::size_t begin, std::size_t end);
  template <bool kReport>
  bool staticCollides(int moving_body, int node, Contact* contact);

  std::vector<BodyPair> static_pairs_;
  std::vector<int> static_pair_index_;  ///< [moving body * world bodies + static body] -> static_pairs_ or -1
  std::vector<BoxNode> tree_;
  int tree_root_ = -1;
  std::vector<BodyPair> moving_pairs_;
  std::size_t pair_count_ = 0;
  std::vector<double> reach_;
};
}  // namespace vrrw_kinematics
