#include <vrrw_evaluation/demo_report.h>

#include <gtest/gtest.h>

using namespace vrrw_evaluation;

TEST(DemoReport, MetricsJsonCarriesTheIssuesKeysAndCountsFailures)
{
  DemoReport report;
  report.scene = "pick_place_drill";
  report.teach_seconds = 9.5;
  report.bag_messages = 1234;
  report.segments = { { "move_to_near_pick", 0.0, 2.0, false, 0.0, "" }, { "move_to_pick", 2.0, 3.2, false, 0.0, "" } };
  report.replay_joint_rms_rad = 1e-3;
  report.replay_object_position_error_m = 0.004;
  report.replay_object_angle_error_deg = 1.5;
  report.physics_rtf = 0.99;
  report.wall_seconds = 200;
  TrialRecord good;
  good.executed = good.success = true;
  TrialRecord skipped;
  skipped.trial = 1;
  skipped.reason = "skipped, near-pick: \"unreachable\"";
  TrialRecord failed;
  failed.trial = 2;
  failed.executed = true;
  failed.reason = "not released";
  report.trials = { good, skipped, failed };
  EXPECT_NEAR(report.successRate(), 1.0 / 3.0, 1e-15);
  const std::string json = metricsJson(report);
  for (const char* key : { "\"teach\": {\"seconds\": 9.5", "\"bag\": {\"messages\": 1234", "\"segments\": [{\"name\": "
                           "\"move_to_near_pick\", \"start\": 0, \"end\": 2}",
                           "\"joint_rms_rad\": 0.001", "\"object_position_error_m\": 0.004",
                           "\"object_angle_error_deg\": 1.5", "\"dmp\": {\"trials\": 3", "\"success_rate\": 0.333333",
                           "\"failures\": [{\"trial\": 1, \"reason\": \"skipped, near-pick: \\\"unreachable\\\"\"}, "
                           "{\"trial\": 2, \"reason\": \"not released\"}]",
                           "\"physics\": {\"rtf\": 0.99}", "\"wall_seconds\": 200" })
    EXPECT_NE(json.find(key), std::string::npos) << key << "\nin\n" << json;
  EXPECT_NE(reportMarkdown(report).find("| DMP success rate | 33.33 % (1 of 3) |"), std::string::npos);
  EXPECT_NE(reportHtml(report).find("<img src=\"strips.png\""), std::string::npos);
}
