#include "dmp_services.h"

#include <algorithm>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/dmp_yaml.h>
#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/msg_conversions.h>

#include "demo_source.h"

namespace vrrw_dmp
{
DmpServices::DmpServices(ros::NodeHandle& private_node)
{
  int basis_count = static_cast<int>(defaults_.basis_count);
  private_node.param("basis_count", basis_count, basis_count);
  defaults_.basis_count = static_cast<std::size_t>(std::max(basis_count, 0));
  private_node.param("alpha", defaults_.alpha, defaults_.alpha);
  private_node.param("K", defaults_.K, defaults_.K);
  double D = -1.0;
  if (private_node.getParam("D", D))
    defaults_.D = D;
  std::string scaling = toString(defaults_.scaling);
  private_node.param("scaling", scaling, scaling);
  defaults_.scaling = amplitudeScalingFromString(scaling);
  defaults_.validate();
  private_node.param("dt", dt_, dt_);
  std::string model;
  if (private_node.getParam("model", model) && !model.empty())
  {
    dmp_ = loadDmp(model);
    ROS_INFO_STREAM("dmp_node: loaded " << model << " (" << dmp_->dofs() << " joints)");
  }
  learn_ = private_node.advertiseService("learn", &DmpServices::learn, this);
  plan_ = private_node.advertiseService("plan", &DmpServices::plan, this);
}

bool DmpServices::learn(Learn::Request& request, Learn::Response& response)
{
  try
  {
    DmpProvenance provenance;
    const auto demo = demonstration(request, provenance.source);
    const Dmp dmp = Dmp::learn(demo, parameters(request), provenance);
    if (!request.model_path.empty())
      saveDmp(dmp, request.model_path);
    for (const auto& warning : dmp.warnings())
      ROS_WARN_STREAM("dmp_node: " << warning);
    response.success = true;
    response.warnings = dmp.warnings();
    response.joint_names = dmp.jointNames();
    response.duration = dmp.demoDuration();
    response.samples = static_cast<int>(demo.points.size());
    response.message = "learned " + std::to_string(dmp.dofs()) + " joints from " + provenance.source + " (" +
                       std::to_string(demo.points.size()) + " samples)";
    dmp_ = dmp;
    ROS_INFO_STREAM("dmp_node: " << response.message);
  }
  catch (const std::exception& e)
  {
    response.success = false;
    response.message = e.what();
    ROS_ERROR_STREAM("dmp_node: learn: " << e.what());
  }
  return true;
}

bool DmpServices::plan(Plan::Request& request, Plan::Response& response)
{
  try
  {
    if (!dmp_)
      throw DmpError("no model yet: call learn first (or start the node with ~model)");
    RolloutRequest rollout;
    rollout.start = request.start;
    rollout.goal = request.goal;
    rollout.tau = request.tau;
    rollout.dt = request.dt == 0.0 ? dt_ : request.dt;
    response.trajectory = vrrw_trajectory::toMsg(dmp_->rollout(rollout));
    response.success = true;
    response.message = "planned " + std::to_string(response.trajectory.points.size()) + " points over " +
                       std::to_string(response.trajectory.points.back().time_from_start.toSec()) + " s";
    for (const auto& warning : dmp_->planWarnings(rollout))
    {
      ROS_WARN_STREAM("dmp_node: plan: " << warning);
      response.message += "; warning: " + warning;
    }
  }
  catch (const std::exception& e)
  {
    response.success = false;
    response.message = e.what();
    ROS_ERROR_STREAM("dmp_node: plan: " << e.what());
  }
  return true;
}

vrrw_trajectory::JointTrajectory DmpServices::demonstration(const Learn::Request& request,
                                                            std::string& source) const
{
  const int sources = !request.bag_path.empty() + !request.csv_path.empty() + !request.trajectory.points.empty();
  if (sources != 1)
    throw DmpError("give exactly one of bag_path, csv_path or trajectory (got " + std::to_string(sources) + ")");
  if (!request.bag_path.empty())
  {
    DemoSource demo = bagSource(request.bag_path, request.robot, request.segment);
    source = demo.source;
    return std::move(demo.trajectory);
  }
  if (!request.csv_path.empty())
  {
    source = request.csv_path;
    return vrrw_trajectory::readCsv(request.csv_path);
  }
  source = "message";
  return vrrw_trajectory::fromMsg(request.trajectory);
}

DmpParameters DmpServices::parameters(const Learn::Request& request) const
{
  DmpParameters p = defaults_;
  if (request.basis_count < 0 || request.alpha < 0.0 || request.K < 0.0 || request.D < 0.0)
    throw DmpError("basis_count, alpha, K and D must be >= 0 (0 means the node's default)");
  if (request.basis_count > 0)
    p.basis_count = static_cast<std::size_t>(request.basis_count);
  if (request.alpha > 0.0)
    p.alpha = request.alpha;
  if (request.K > 0.0)
    p.K = request.K;
  if (request.D > 0.0)
    p.D = request.D;
  if (!request.scaling.empty())
    p.scaling = amplitudeScalingFromString(request.scaling);
  return p;
}
}  // namespace vrrw_dmp
