#pragma once
// dmp_node's services: ~learn (a DMP from a bag, a CSV or a JointTrajectory) and ~plan (a rollout of the last
// model learned or loaded). Every failure is an answer (success false, one line), never an exception out.
#include <optional>
#include <string>

#include <ros/ros.h>
#include <vrrw_dmp/Learn.h>
#include <vrrw_dmp/Plan.h>
#include <vrrw_dmp/dmp.h>

namespace vrrw_dmp
{
class DmpServices
{
public:
  /// \brief Reads the learning defaults (~basis_count ~alpha ~K ~D ~scaling), ~dt and ~model (loaded now) from
  /// \a private_node and advertises ~learn and ~plan there; throws DmpError for a bad parameter or model.
  explicit DmpServices(ros::NodeHandle& private_node);

private:
  bool learn(Learn::Request& request, Learn::Response& response);
  bool plan(Plan::Request& request, Plan::Response& response);
  /// \brief The request's one demonstration; \a source names it for the model's provenance.
  vrrw_trajectory::JointTrajectory demonstration(const Learn::Request& request, std::string& source) const;
  /// \brief The node's defaults with the request's non-zero values; throws DmpError for a negative one.
  DmpParameters parameters(const Learn::Request& request) const;

  DmpParameters defaults_;
  double dt_ = 0.01;  ///< s between planned samples when a request gives none
  std::optional<Dmp> dmp_;  ///< the model ~plan rolls out (ros::spin: one callback at a time)
  ros::ServiceServer learn_;
  ros::ServiceServer plan_;
};
}  // namespace vrrw_dmp
