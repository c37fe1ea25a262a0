#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/orientation_dmp.h>

namespace vrrw_dmp
{
/// \brief A TCP pose: position (m) and unit quaternion.
struct CartesianPose
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// \brief One sample of a Cartesian path, demonstrated (velocities unused) or rolled out.
struct CartesianSample
{
  double time = 0.0;  ///< s
  CartesianPose pose;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          ///< m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< rad/s, world axes
};

/// \brief A new start, goal and speed for a Cartesian rollout; unset poses and tau <= 0: as demonstrated.
struct CartesianRolloutRequest
{
  std::optional<CartesianPose> start;
  std::optional<CartesianPose> goal;
  double tau = 0.0;  ///< s; the demonstration has tau = its duration
  double dt = 0.01;  ///< output sample period, s
  double position_tolerance = 5e-4;            ///< m: after tau the rollout ends once this close to the goal,
  double angle_tolerance = 0.1 * M_PI / 180.0;  ///< rad: this close in orientation,
  double rest_speed = 5e-3;                    ///< m/s: moving slower than this
  double rest_angular_speed = 1e-2;            ///< rad/s: and turning slower than this
};

/// \brief How closely a model reproduces its demonstration: RMS over the demonstrated samples of the
/// rollout with the demonstrated start, goal and tau (linearly interpolated at the samples' times).
struct CartesianFit
{
  double position_rmse = 0.0;  ///< m
  double angle_rmse = 0.0;     ///< rad
};

/// \brief A Cartesian DMP of a TCP path: a Dmp per position axis (x, y, z in the path's frame, with all of
/// Dmp's features: scaling per axis, exact steps, limits) and the unit-quaternion OrientationDmp of Ude et
/// al. 2014, sharing tau, the basis and the phase. Rolled out together; the rollout ends at the first sample
/// after tau within the request's tolerances of the goal (no creeping over the last micrometres: a 23 s
/// demonstration ends a few tenths of a second after tau, not tens of seconds), or at kSettlingFactor tau.
class CartesianDmp
{
public:
  /// \brief Learns from a path of at least 3 samples at strictly increasing finite times, finite positions
  /// and unit quaternions. Throws DmpError naming the sample.
  static CartesianDmp learn(const std::vector<CartesianSample>& demo, const DmpParameters& parameters,
                            const DmpProvenance& provenance = {});

  /// \brief From its parts (the model loader); both must share the parameters, basis and duration.
  CartesianDmp(Dmp position, OrientationDmp orientation);

  /// \brief Throws DmpError for a bad request (dt, tau, a pose not finite or not unit) or one whose worst
  /// case exceeds Dmp::kMaxRolloutSamples, before any work.
  std::vector<CartesianSample> rollout(const CartesianRolloutRequest& request) const;

  const Dmp& position() const { return position_; }
  const OrientationDmp& orientation() const { return orientation_; }
  CartesianPose demoStart() const;
  CartesianPose demoGoal() const;
  double demoDuration() const { return position_.demoDuration(); }
  /// \brief The position's and the orientation's learning warnings.
  std::vector<std::string> warnings() const;

private:
  Dmp position_;
  OrientationDmp orientation_;
};

/// \brief The model's CartesianFit on \a demo.
CartesianFit reproductionError(const CartesianDmp& dmp, const std::vector<CartesianSample>& demo);

/// \brief The pose at time t of a path, positions interpolated linearly and orientations by slerp (clamped).
CartesianPose poseAt(const std::vector<CartesianSample>& path, double t);
}  // namespace vrrw_dmp
