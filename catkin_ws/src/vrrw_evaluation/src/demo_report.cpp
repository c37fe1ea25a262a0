#include <vrrw_evaluation/demo_report.h>
#include <vrrw_evaluation/evaluation_error.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace vrrw_evaluation
{
namespace
{
std::string number(double value, int digits = 6)
{
  if (!std::isfinite(value))
    return "null";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}


std::string numberMap(const std::map<std::string, double>& values)
{
  std::string out = "{";
  for (const auto& [name, value] : values)
    out += (out.size() > 1 ? ", " : "") + jsonString(name) + ": " + number(value);
  return out + "}";
}

std::string html(const std::string& text)
{
  std::string out;
  for (char c : text)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

/// The metrics table shared by report.md and index.html: rows of (what, value).
std::vector<std::pair<std::string, std::string>> metricRows(const DemoReport& r)
{
  std::vector<std::pair<std::string, std::string>> rows;
  rows.push_back({ "teach duration", number(r.teach_seconds, 4) + " s (" + r.teach_source + ")" });
  std::string counts;
  for (const auto& [topic, count] : r.message_counts)
    counts += (counts.empty() ? "" : ", ") + topic + " " + std::to_string(count);
  rows.push_back({ "demonstration bag messages", std::to_string(r.bag_messages) + (counts.empty() ? "" : " (" + counts + ")") });
  for (const Segment& s : r.segments)
    rows.push_back({ "segment " + s.name, number(s.start, 4) + " .. " + number(s.end, 4) + " s" });
  rows.push_back({ "replay joint error (RMS)", number(r.replay_joint_rms_rad, 3) + " rad" });
  for (const auto& [name, rms] : r.replay_segment_rms_rad)
    rows.push_back({ "replay joint error, " + name, number(rms, 3) + " rad" });
  rows.push_back({ "replay drill position error", number(r.replay_object_position_error_m * 1000, 3) + " mm" });
  rows.push_back({ "replay drill angle error", number(r.replay_object_angle_error_deg, 3) + " deg" });
  rows.push_back({ "skill learned from the bag", r.skill.file + " in " + number(r.skill.learn_seconds, 3) + " s" });
  rows.push_back({ "learned grasp vs the script's", number(r.skill.grasp_error_mm, 3) + " mm, " +
                                                      number(r.skill.grasp_error_deg, 3) + " deg" });
  for (const auto& [name, rmse] : r.dmp_fit_rmse_rad)
    rows.push_back({ "DMP fit RMSE, " + name, number(rmse, 3) + " rad (joints), " +
                                                  number(r.skill.cartesian_fit_rmse_m.count(name) ?
                                                             1000 * r.skill.cartesian_fit_rmse_m.at(name) : 0.0, 3) +
                                                  " mm (TCP)" });
  rows.push_back({ "DMP success rate", number(100 * r.successRate(), 4) + " % (" + std::to_string(r.successCount()) +
                                           " of " + std::to_string(r.trialCount()) + ")" });
  rows.push_back({ "planning time (teach)", number(r.plan_ms, 4) + " ms" });
  double ik = 0.0;
  for (const TrialRecord& t : r.trials)
    ik += t.ik_ms;
  rows.push_back({ "planning time per trial (IK, rollouts, checks)",
                   number(r.trials.empty() ? 0.0 : ik / double(r.trials.size()), 4) + " ms" });
  rows.push_back({ "physics real-time factor", number(r.physics_rtf, 4) });
  for (const auto& [stage, seconds] : r.stage_seconds)
    rows.push_back({ "wall time, " + stage, number(seconds, 4) + " s" });
  rows.push_back({ "wall time, whole run", number(r.wall_seconds, 4) + " s" });
  return rows;
}

std::string trialLine(const TrialRecord& t, const char* separator)
{
  std::ostringstream line;
  line << t.trial << separator << number(t.x, 4) << separator << number(t.y, 4) << separator << number(t.yaw_deg, 3)
       << separator << (t.executed ? (t.success ? "success" : "failed") : "skipped") << separator
       << (t.executed ? number(t.final_error_m * 100, 3) : "-") << separator
       << (t.executed ? number(t.final_angle_deg, 3) : "-") << separator << t.reason;
  return line.str();
}
}  // namespace

std::string jsonString(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    if (c == '\n')
    {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

int DemoReport::successCount() const
{
  int n = 0;
  for (const TrialRecord& t : trials)
    n += t.success ? 1 : 0;
  return n;
}

double DemoReport::successRate() const
{
  return trials.empty() ? 0.0 : double(successCount()) / double(trials.size());
}

std::string metricsJson(const DemoReport& r)
{
  std::ostringstream j;
  j << "{\n  \"scene\": " << jsonString(r.scene) << ",\n  \"seed\": " << r.seed << ",\n";
  j << "  \"teach\": {\"seconds\": " << number(r.teach_seconds) << ", \"start_stamp\": " << number(r.teach_start_stamp, 17)
    << ", \"source\": " << jsonString(r.teach_source)
    << ", \"plan_ms\": " << number(r.plan_ms) << ",\n    \"interfaces\": {";
  for (std::size_t i = 0; i < r.teach_interfaces.size(); ++i)
  {
    j << (i ? ", " : "") << jsonString(r.teach_interfaces[i].first) << ": [";
    for (std::size_t k = 0; k < r.teach_interfaces[i].second.size(); ++k)
      j << (k ? ", " : "") << jsonString(r.teach_interfaces[i].second[k]);
    j << "]";
  }
  j << "}},\n";
  j << "  \"bag\": {\"messages\": " << r.bag_messages << ", \"file\": " << jsonString(r.bag_file) << ", \"topics\": {";
  std::string sep;
  for (const auto& [topic, count] : r.message_counts)
    j << sep << jsonString(topic) << ": " << count, sep = ", ";
  j << "}},\n  \"segments\": [";
  sep.clear();
  for (const Segment& s : r.segments)
    j << sep << "{\"name\": " << jsonString(s.name) << ", \"start\": " << number(s.start) << ", \"end\": " << number(s.end)
      << "}",
        sep = ", ";
  j << "],\n  \"skill\": {\"file\": " << jsonString(r.skill.file) << ", \"learn_seconds\": " << number(r.skill.learn_seconds)
    << ", \"grasp_learned_m\": [" << number(r.skill.grasp_learned[0]) << ", " << number(r.skill.grasp_learned[1]) << ", "
    << number(r.skill.grasp_learned[2]) << "], \"grasp_taught_m\": [" << number(r.skill.grasp_taught[0]) << ", "
    << number(r.skill.grasp_taught[1]) << ", " << number(r.skill.grasp_taught[2]) << "], \"grasp_error_mm\": "
    << number(r.skill.grasp_error_mm) << ", \"grasp_error_deg\": " << number(r.skill.grasp_error_deg)
    << ", \"cartesian_fit_rmse_m\": " << numberMap(r.skill.cartesian_fit_rmse_m)
    << ", \"cartesian_fit_rmse_deg\": " << numberMap(r.skill.cartesian_fit_rmse_deg) << "},\n";
  j << "  \"replay\": {\"joint_rms_rad\": " << number(r.replay_joint_rms_rad)
    << ", \"segment_joint_rms_rad\": " << numberMap(r.replay_segment_rms_rad)
    << ", \"object_position_error_m\": " << number(r.replay_object_position_error_m)
    << ", \"object_angle_error_deg\": " << number(r.replay_object_angle_error_deg) << "},\n";
  j << "  \"dmp\": {\"trials\": " << r.trialCount() << ", \"successes\": " << r.successCount()
    << ", \"success_rate\": " << number(r.successRate()) << ", \"fit_rmse_rad\": " << numberMap(r.dmp_fit_rmse_rad)
    << ",\n    \"failures\": [";
  sep.clear();
  for (const TrialRecord& t : r.trials)
    if (!t.success)
      j << sep << "{\"trial\": " << t.trial << ", \"reason\": " << jsonString(t.reason) << "}", sep = ", ";
  j << "],\n    \"trial_results\": [";
  sep.clear();
  for (const TrialRecord& t : r.trials)
    j << sep << "\n      {\"trial\": " << t.trial << ", \"x\": " << number(t.x) << ", \"y\": " << number(t.y)
      << ", \"yaw_deg\": " << number(t.yaw_deg) << ", \"executed\": " << (t.executed ? "true" : "false")
      << ", \"success\": " << (t.success ? "true" : "false") << ", \"final_error_m\": " << number(t.final_error_m)
      << ", \"final_angle_deg\": " << number(t.final_angle_deg) << ", \"ik_ms\": " << number(t.ik_ms)
      << ", \"cycle_seconds\": " << number(t.cycle_seconds)
      << ", \"reason\": " << jsonString(t.reason) << "}",
        sep = ",";
  j << "]},\n  \"physics\": {\"rtf\": " << number(r.physics_rtf) << "},\n";
  j << "  \"stage_seconds\": " << numberMap(r.stage_seconds) << ",\n";
  j << "  \"wall_seconds\": " << number(r.wall_seconds) << "\n}\n";
  return j.str();
}

std::string reportMarkdown(const DemoReport& r)
{
  std::ostringstream md;
  md << "# vrrw demo: " << r.scene << "\n\nTeach, replay (direct imitation) and DMP generalization of a drill "
     << "pick-and-place in physics (seed " << r.seed << ").\n\n";
  md << "![frame strips](strips.png)\n\n![joints](joints.png)\n\n![top view](top_view.png)\n\n";
  md << "| metric | value |\n|---|---|\n";
  for (const auto& [what, value] : metricRows(r))
    md << "| " << what << " | " << value << " |\n";
  md << "\n## DMP trials\n\n| trial | x (m) | y (m) | yaw (deg) | result | final error (cm) | final yaw error (deg) | "
        "reason |\n|---|---|---|---|---|---|---|---|\n";
  for (const TrialRecord& t : r.trials)
    md << "| " << trialLine(t, " | ") << " |\n";
  return md.str();
}

std::string reportHtml(const DemoReport& r)
{
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>vrrw demo: " << html(r.scene)
    << "</title>\n<style>body{font-family:sans-serif;max-width:1200px;margin:auto}table{border-collapse:collapse}"
       "td,th{border:1px solid #ccc;padding:2px 8px}img{max-width:100%}</style></head><body>\n";
  h << "<h1>vrrw demo: " << html(r.scene) << "</h1>\n<p>Teach, replay (direct imitation) and DMP generalization of a "
    << "drill pick-and-place in physics (seed " << r.seed << "). DMP success: " << r.successCount() << " of "
    << r.trialCount() << ".</p>\n";
  h << "<h2>Frames at the six instruction boundaries</h2>\n<p>Rows: demonstration, replay, DMP trials.</p>\n"
    << "<img src=\"strips.png\" alt=\"frame strips\">\n";
  h << "<h2>Joints</h2>\n<img src=\"joints.png\" alt=\"joint plots\">\n<h2>Top view</h2>\n"
    << "<img src=\"top_view.png\" alt=\"top view\">\n<h2>Metrics</h2>\n<table>\n";
  for (const auto& [what, value] : metricRows(r))
    h << "<tr><td>" << html(what) << "</td><td>" << html(value) << "</td></tr>\n";
  h << "</table>\n<h2>DMP trials</h2>\n<table>\n<tr><th>trial</th><th>x (m)</th><th>y (m)</th><th>yaw (deg)</th>"
    << "<th>result</th><th>final error (cm)</th><th>final yaw error (deg)</th><th>reason</th></tr>\n";
  for (const TrialRecord& t : r.trials)
  {
    std::string cells = trialLine(t, "</td><td>");
    h << "<tr><td>" << cells << "</td></tr>\n";
  }
  h << "</table>\n<p>Raw numbers: <a href=\"metrics.json\">metrics.json</a>, <a href=\"report.md\">report.md</a>.</p>\n"
    << "</body></html>\n";
  return h.str();
}

void writeReport(const DemoReport& report, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  const std::pair<const char*, std::string> files[] = { { "metrics.json", metricsJson(report) },
                                                         { "report.md", reportMarkdown(report) },
                                                         { "index.html", reportHtml(report) } };
  for (const auto& [name, text] : files)
  {
    const std::string path = directory + "/" + name;
    std::ofstream out(path);
    out << text;
    if (!out.good())
      throw EvaluationError(path + ": cannot write");
  }
}
}  // namespace vrrw_evaluation
