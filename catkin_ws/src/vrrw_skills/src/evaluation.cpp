#include <vrrw_skills/evaluation.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include <vrrw_skills/poses.h>

#include "json_text.h"

namespace vrrw_skills
{
namespace
{
std::string number(double value, int digits = 6)
{
  if (!std::isfinite(value))
    return "null";
  char text[40];
  std::snprintf(text, sizeof(text), "%.*g", digits, value);
  return text;
}

std::string htmlEscaped(const std::string& text)
{
  std::string out;
  for (char c : text)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

std::string trialJson(const TrialResult& t)
{
  return "{\"trial\":" + std::to_string(t.trial) + ",\"x\":" + number(t.x) + ",\"y\":" + number(t.y) +
         ",\"yaw_deg\":" + number(t.yaw_deg) + ",\"success\":" + (t.success ? "true" : "false") +
         ",\"reachable\":" + (t.reachable ? "true" : "false") + ",\"place_error_m\":" + number(t.place_error_m) +
         ",\"cycle_seconds\":" + number(t.cycle_seconds) + ",\"planning_ms\":" + number(t.planning_ms) +
         ",\"reason\":" + jsonString(t.reason) + "}";
}

std::string headJson(const EvaluationReport& r)
{
  std::string failures;
  for (const TrialResult& t : r.trials)
    if (!t.success)
      failures += std::string(failures.empty() ? "" : ",") + "{\"trial\":" + std::to_string(t.trial) +
                  ",\"reason\":" + jsonString(t.reason) + "}";
  double cycle = 0.0, planning = 0.0;
  std::size_t ran = 0;
  for (const TrialResult& t : r.trials)
    if (t.success)
    {
      cycle += t.cycle_seconds;
      planning += t.planning_ms;
      ++ran;
    }
  return "\"skill\":" + jsonString(r.skill_file) + ",\"scene\":" + jsonString(r.scene) + ",\"robot\":" +
         jsonString(r.robot) + ",\"taught_robot\":" + jsonString(r.taught_robot) + ",\"object\":" +
         jsonString(r.object) + ",\"seed\":" + std::to_string(r.options.seed) + ",\"spread\":[" +
         number(r.options.spread.x) + "," + number(r.options.spread.y) + "," +
         number(r.options.spread.yaw * 180.0 / M_PI) + "],\"trials\":" + std::to_string(r.trials.size()) +
         ",\"successes\":" + std::to_string(r.successes()) + ",\"success_rate\":" + number(r.successRate()) +
         ",\"reachable_rate\":" + number(r.reachableRate()) + ",\"mean_cycle_seconds\":" +
         number(ran ? cycle / ran : 0.0) + ",\"mean_planning_ms\":" + number(ran ? planning / ran : 0.0) +
         ",\"failures\":[" + failures + "],\"wall_seconds\":" + number(r.wall_seconds);
}
}  // namespace

std::size_t EvaluationReport::successes() const
{
  std::size_t count = 0;
  for (const TrialResult& t : trials)
    count += t.success;
  return count;
}

double EvaluationReport::successRate() const
{
  return trials.empty() ? 0.0 : static_cast<double>(successes()) / static_cast<double>(trials.size());
}

double EvaluationReport::reachableRate() const
{
  std::size_t count = 0;
  for (const TrialResult& t : trials)
    count += t.reachable;
  return trials.empty() ? 0.0 : static_cast<double>(count) / static_cast<double>(trials.size());
}

std::vector<PlanarPose> evaluationPoses(const Skill& skill, const EvaluationOptions& options)
{
  return sampleTrialPoses(planarPose(toIsometry(skill.object_start)), options.spread, options.trials, options.seed);
}

std::string metricsJson(const EvaluationReport& report)
{
  std::string trials;
  for (const TrialResult& t : report.trials)
    trials += std::string(trials.empty() ? "" : ",\n  ") + trialJson(t);
  return "{" + headJson(report) + ",\n \"trial_results\":[\n  " + trials + "]}\n";
}

std::string summaryJson(const EvaluationReport& report)
{
  std::string trials;
  for (const TrialResult& t : report.trials)
    trials += std::string(trials.empty() ? "" : ",") + trialJson(t);
  return "{" + headJson(report) + ",\"trial_results\":[" + trials + "]}";
}

std::string tracksJson(const EvaluationReport& report)
{
  std::ostringstream out;
  out << "{\"start\":[" << number(report.object_start.position.x()) << "," << number(report.object_start.position.y())
      << "],\"end\":[" << number(report.object_end.position.x()) << "," << number(report.object_end.position.y())
      << "],\"radius\":" << number(report.place_radius) << ",\"title\":"
      << jsonString(report.robot + ": " + std::to_string(report.successes()) + " of " +
                    std::to_string(report.trials.size()) + " trials")
      << ",\"trials\":[";
  for (std::size_t i = 0; i < report.trials.size(); ++i)
  {
    const TrialResult& t = report.trials[i];
    out << (i ? "," : "") << "{\"x\":" << number(t.x) << ",\"y\":" << number(t.y) << ",\"yaw_deg\":" << number(t.yaw_deg)
        << ",\"success\":" << (t.success ? "true" : "false") << ",\"end\":[" << number(t.object_end.x()) << ","
        << number(t.object_end.y()) << "],\"tcp\":[";
    for (std::size_t k = 0; k < t.tcp_path.size(); ++k)
      out << (k ? "," : "") << "[" << number(t.tcp_path[k].x(), 5) << "," << number(t.tcp_path[k].y(), 5) << "]";
    out << "]}";
  }
  out << "]}\n";
  return out.str();
}

std::string indexHtml(const EvaluationReport& r)
{
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>skill evaluation: " << htmlEscaped(r.skill_file)
      << "</title>\n<style>body{font-family:sans-serif;margin:2em}td,th{padding:2px 8px;text-align:right}"
         "td.l{text-align:left}.f{color:#b00}</style></head><body>\n";
  out << "<h1>" << htmlEscaped(r.skill_file) << " on " << htmlEscaped(r.robot) << " in " << htmlEscaped(r.scene)
      << "</h1>\n<p>" << r.successes() << " of " << r.trials.size() << " trials succeeded ("
      << number(100.0 * r.successRate(), 3) << " %); every goal reachable in " << number(100.0 * r.reachableRate(), 3)
      << " % of the poses. Taught on " << htmlEscaped(r.taught_robot) << ", object '" << htmlEscaped(r.object)
      << "', seed " << r.options.seed << ", spread +-" << number(r.options.spread.x * 100, 3) << " cm, +-"
      << number(r.options.spread.y * 100, 3) << " cm, +-" << number(r.options.spread.yaw * 180 / M_PI, 3)
      << " deg; " << number(r.wall_seconds, 4) << " s.</p>\n";
  out << "<p><img src=\"top_view.png\" alt=\"top view: object starts, TCP paths, place area\"></p>\n";
  out << "<table><tr><th>trial</th><th>x m</th><th>y m</th><th>yaw deg</th><th>result</th><th>place error cm</th>"
         "<th>cycle s</th><th>planning ms</th><th class=\"l\">reason</th></tr>\n";
  for (const TrialResult& t : r.trials)
    out << "<tr><td>" << t.trial << "</td><td>" << number(t.x, 4) << "</td><td>" << number(t.y, 4) << "</td><td>"
        << number(t.yaw_deg, 3) << "</td><td" << (t.success ? ">success" : " class=\"f\">failed") << "</td><td>"
        << number(t.place_error_m * 100, 3) << "</td><td>" << number(t.cycle_seconds, 4) << "</td><td>"
        << number(t.planning_ms, 4) << "</td><td class=\"l\">" << htmlEscaped(t.reason) << "</td></tr>\n";
  out << "</table>\n<p>metrics.json has the same figures.</p></body></html>\n";
  return out.str();
}
}  // namespace vrrw_skills
