#pragma once
#include <Eigen/Geometry>
#include <memory>

class btCollisionObject;
class btDiscreteDynamicsWorld;
class btRigidBody;
class btSphereShape;
struct btDefaultMotionState;

namespace vrrw_physics
{
/// \brief One tracked hand as Bullet sees it: a kinematic sphere that pushes links and objects by contact.
///
/// A tracker reports poses at its own rate (30-100 Hz) while physics steps at 1 kHz: the sphere glides to
/// each new pose over the time since the previous one (at most kMaxGlide), so it meets links and objects
/// with the tracker's velocity instead of a jump of one step.
class KinematicHand
{
public:
  static constexpr double kMaxGlide = 0.1;  ///< s

  KinematicHand(btDiscreteDynamicsWorld& world, double radius, const Eigen::Isometry3d& pose, double now);
  ~KinematicHand();
  KinematicHand(const KinematicHand&) = delete;
  KinematicHand& operator=(const KinematicHand&) = delete;

  double radius() const { return radius_; }
  /// \brief Simulated time of the last tracked pose.
  double lastUpdate() const { return last_update_; }
  const btCollisionObject* body() const;
  /// \brief A new tracked pose at simulated time `now`.
  void track(const Eigen::Isometry3d& pose, double now);
  /// \brief Places the sphere where it is at the end of the step that starts at `now`.
  void advance(double now, double dt);

private:
  btDiscreteDynamicsWorld& world_;
  double radius_;
  std::unique_ptr<btSphereShape> shape_;
  std::unique_ptr<btDefaultMotionState> motion_;
  std::unique_ptr<btRigidBody> body_;
  Eigen::Isometry3d from_, to_;
  double start_;
  double duration_ = 0.0;
  double last_update_;
};
}  // namespace vrrw_physics
