// vrrw_dmp: learn a DMP from a demonstration CSV, roll it out to a new start/goal/tau, plot the result.
#include <iomanip>
#include <iostream>
#include <sstream>

#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/options.h>
#include <vrrw_common/run_program.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_dmp/demo_fit.h>
#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/dmp_yaml.h>
#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/trajectory_error.h>

#include "../src/ros/demo_source.h"

namespace
{
using vrrw_common::OptionError;
using vrrw_common::Options;

const char* const kUsage =
    "usage: vrrw_dmp learn --demo FILE.csv|FILE.bag --out MODEL.yaml [--robot R] [--segment NAME] [--basis N]\n"
    "                      [--alpha A] [--K K] [--D D] [--scaling goal|amplitude|auto]\n"
    "       vrrw_dmp rollout --model MODEL.yaml --out FILE.csv [--start q1,..] [--goal q1,..] [--tau T] [--dt DT]\n"
    "       vrrw_dmp plot --demo FILE.csv --rollout FILE.csv [--rollout FILE2.csv ..] --out FILE.png [--title T]\n"
    "CSV: header 't,<joint>..,<joint>_vel..', rows t, q1..qn, qd1..qdn. Values starting with '-' work as\n"
    "--goal=-0.5,1.2 or --goal -0.5,1.2.\n";

vrrw_dmp::DemoSource loadSource(const Options& options)
{
  const std::string path = options.text("demo");
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".bag") == 0)
    return vrrw_dmp::bagSource(path, options.text("robot", ""), options.text("segment", ""));
  if (options.has("robot") || options.has("segment"))
    throw OptionError("--robot and --segment need a recorded bag as --demo (FILE.bag), not " + path);
  return vrrw_dmp::csvSource(path);
}

int learn(int argc, char** argv)
{
  const Options options(argc, argv, 2, { "demo", "out", "robot", "segment", "basis", "alpha", "K", "D", "scaling" });
  options.expectPositional({});
  const std::string out = options.text("out");
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = options.count("basis", parameters.basis_count, 0, 1000000000);
  parameters.alpha = options.number("alpha", parameters.alpha);
  parameters.K = options.number("K", parameters.K);
  if (options.has("D"))
    parameters.D = options.number("D", 0.0);
  parameters.scaling = vrrw_dmp::amplitudeScalingFromString(options.text("scaling", "goal"));
  parameters.validate();

  const vrrw_dmp::DemoSource demo = loadSource(options);
  vrrw_dmp::DmpProvenance provenance;
  provenance.source = demo.source;
  const auto dmp = vrrw_dmp::Dmp::learn(demo.trajectory, parameters, provenance);
  for (const auto& warning : dmp.warnings())
    std::cerr << "vrrw dmp: warning: " << warning << "\n";
  vrrw_dmp::saveDmp(dmp, out);
  const double rmse = vrrw_dmp::reproductionRmse(dmp, demo.trajectory);
  std::cout << "learned " << dmp.dofs() << " joints from " << demo.source << " (" << demo.trajectory.points.size()
            << " samples, " << dmp.demoDuration() << " s), N = " << parameters.basis_count << ", reproduction RMSE "
            << std::setprecision(3) << rmse << std::setprecision(6) << " rad -> " << out << "\n";  // %.3g
  for (const auto& line : vrrw_dmp::fitAdvice(demo, parameters, rmse))
    std::cout << "advice: " << line << "\n";
  return 0;
}

int rollout(int argc, char** argv)
{
  const Options options(argc, argv, 2, { "model", "out", "start", "goal", "tau", "dt" });
  options.expectPositional({});
  const auto dmp = vrrw_dmp::loadDmp(options.text("model"));
  const std::string out = options.text("out");
  vrrw_dmp::RolloutRequest request;
  request.start = options.list("start");
  request.goal = options.list("goal");
  request.tau = options.number("tau", 0.0);
  if (options.has("tau") && !(request.tau > 0.0))
    throw OptionError("--tau: must be > 0");
  request.dt = options.number("dt", request.dt);
  const auto trajectory = dmp.rollout(request);
  for (const auto& warning : dmp.planWarnings(request))
    std::cerr << "vrrw dmp: warning: " << warning << "\n";
  vrrw_trajectory::writeCsv(out, trajectory);
  std::cout << "rolled out " << trajectory.points.size() << " samples over " << trajectory.duration() << " s -> "
            << out << "\n";
  return 0;
}

std::string jsonString(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
      quoted += '\\';
    if (static_cast<unsigned char>(c) < 0x20)
      quoted += ' ';
    else
      quoted += c;
  }
  return quoted + "\"";
}

void appendSeries(std::ostringstream& json, const std::string& label, const vrrw_trajectory::JointTrajectory& data,
                  const std::vector<std::string>& joints, const std::string& path)
{
  std::vector<std::size_t> column;
  try
  {
    column = vrrw_common::jointMapping(data.joint_names, joints);
  }
  catch (const vrrw_common::JointMappingError& e)
  {
    throw vrrw_trajectory::TrajectoryError(path + ": " + e.what() + " (the demonstration has them)");
  }
  json << "{\"label\":" << jsonString(label) << ",\"t\":[";
  for (std::size_t k = 0; k < data.points.size(); ++k)
    json << (k ? "," : "") << data.points[k].time - data.points.front().time;
  json << "],\"q\":[";
  for (std::size_t j = 0; j < column.size(); ++j)
  {
    json << (j ? ",[" : "[");
    for (std::size_t k = 0; k < data.points.size(); ++k)
      json << (k ? "," : "") << data.points[k].positions[column[j]];
    json << "]";
  }
  json << "]}";
}

int plot(int argc, char** argv)
{
  const Options options(argc, argv, 2, { "demo", "rollout", "out", "title" });
  options.expectPositional({});
  const std::string demo_path = options.text("demo");
  const std::string out = options.text("out");
  const auto rollouts = options.all("rollout");
  if (rollouts.empty())
    throw OptionError("--rollout is required (give it once per DMP trajectory)");
  const auto demo = vrrw_trajectory::readCsv(demo_path);
  std::ostringstream json;
  json.precision(9);
  json << "{\"out\":" << jsonString(out) << ",\"title\":" << jsonString(options.text("title", "")) << ",\"joints\":[";
  for (std::size_t j = 0; j < demo.joint_names.size(); ++j)
    json << (j ? "," : "") << jsonString(demo.joint_names[j]);
  json << "],\"series\":[";
  appendSeries(json, "demonstration", demo, demo.joint_names, demo_path);
  for (const auto& path : rollouts)
  {
    json << ",";
    appendSeries(json, rollouts.size() == 1 ? "DMP" : "DMP " + path.substr(path.find_last_of('/') + 1),
                 vrrw_trajectory::readCsv(path), demo.joint_names, path);
  }
  json << "]}";
  const std::string data = json.str();
  vrrw_common::ProgramStreams streams;
  streams.input = &data;  // the plot script reads the series as JSON on its standard input
  const int status = vrrw_common::runProgram({ "/usr/bin/python3", std::string(VRRW_DMP_SCRIPTS) + "/plot_dmp.py" },
                                             streams);
  if (status != 0)
    throw std::runtime_error("plot: the plot script failed (exit " + std::to_string(status) + ")");
  std::cout << "plotted " << demo.joint_names.size() << " joints -> " << out << "\n";
  return 0;
}

/// 2 for bad input (an option, a model, CSV or bag it cannot read, parameters it refuses, a file it cannot
/// write), 1 for a failure while running (the plot script).
int exitCodeOf(const std::exception& e)
{
  const bool bad_input = dynamic_cast<const OptionError*>(&e) || dynamic_cast<const vrrw_dmp::DmpError*>(&e) ||
                         dynamic_cast<const vrrw_trajectory::TrajectoryError*>(&e) ||
                         dynamic_cast<const vrrw_demos::DemoError*>(&e);
  return bad_input ? 2 : 1;
}
}  // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  try
  {
    if (command == "learn")
      return learn(argc, argv);
    if (command == "rollout")
      return rollout(argc, argv);
    if (command == "plot")
      return plot(argc, argv);
    if (command == "help" || command == "--help" || command == "-h")
    {
      std::cout << kUsage;
      return 0;
    }
    std::cerr << "vrrw dmp: unknown command '" << command << "'\n" << kUsage;
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw dmp " << command << ": " << e.what() << "\n";
    return exitCodeOf(e);
  }
}
