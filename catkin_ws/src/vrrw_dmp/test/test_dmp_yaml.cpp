#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/dmp_yaml.h>

#include "demo_fixture.h"

using vrrw_dmp::Dmp;
using vrrw_dmp::DmpError;

namespace
{
Dmp learned()
{
  auto demo = vrrw_dmp_test::sample(vrrw_dmp_test::SmoothDemo{}, 300, 0.3);
  for (auto& point : demo.points)
    point.positions[4] = 0.2 + 0.3 * std::pow(std::sin(M_PI * point.time / 2.0), 2);
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = 40;
  parameters.K = 120.0;
  parameters.scaling = vrrw_dmp::AmplitudeScaling::automatic;
  vrrw_dmp::DmpProvenance provenance;
  provenance.source = "demo.csv";
  return Dmp::learn(demo, parameters, provenance);
}

std::string errorOf(const std::string& text)
{
  try
  {
    vrrw_dmp::fromYaml(text, "model.yaml");
  }
  catch (const DmpError& e)
  {
    return e.what();
  }
  return "no error";
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}
}  // namespace

TEST(DmpYaml, SaveLoadGivesIdenticalRollouts)
{
  const Dmp original = learned();
  const std::string path = ::testing::TempDir() + "vrrw_dmp_model_" + std::to_string(::getpid()) + ".yaml";
  vrrw_dmp::saveDmp(original, path);
  const Dmp loaded = vrrw_dmp::loadDmp(path);
  std::remove(path.c_str());

  EXPECT_EQ(loaded.jointNames(), original.jointNames());
  EXPECT_EQ(loaded.weights(), original.weights());
  EXPECT_EQ(loaded.basis().centers(), original.basis().centers());
  EXPECT_EQ(loaded.basis().widths(), original.basis().widths());
  EXPECT_EQ(loaded.jointScaling(), original.jointScaling());
  EXPECT_EQ(loaded.warnings(), original.warnings());
  EXPECT_EQ(loaded.parameters().K, 120.0);
  EXPECT_EQ(loaded.parameters().damping(), original.parameters().damping());
  EXPECT_EQ(loaded.provenance().source, "demo.csv");
  EXPECT_EQ(loaded.provenance().samples, 300u);
  EXPECT_EQ(loaded.provenance().demo_checksum, original.provenance().demo_checksum);
  EXPECT_EQ(loaded.provenance().created, original.provenance().created);

  vrrw_dmp::RolloutRequest request;
  request.goal = { 0.3, -0.2, 1.0, 0.5, 0.2, -0.4 };
  request.tau = 3.0;
  request.dt = 0.004;
  const auto a = original.rollout(request);
  const auto b = loaded.rollout(request);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k)
  {
    EXPECT_EQ(a.points[k].positions, b.points[k].positions);
    EXPECT_EQ(a.points[k].velocities, b.points[k].velocities);
  }
}

TEST(DmpYaml, BadModelFilesNameTheField)
{
  const std::string good = vrrw_dmp::toYaml(learned());
  EXPECT_EQ(errorOf(good), "no error");
  EXPECT_EQ(errorOf(replaced(good, "format: vrrw_dmp/1", "format: other/2")),
            "model.yaml: format: 'other/2' is not 'vrrw_dmp/1'");
  EXPECT_EQ(errorOf(replaced(good, "  K: 120", "  K: -120")), "model.yaml: K = -120: must be a finite number > 0");
  EXPECT_EQ(errorOf(replaced(good, "  basis_count: 40", "  basis_count: 0")),
            "model.yaml: parameters.basis_count: 0 must be > 0 and at most the limit of 10000");
  EXPECT_EQ(errorOf(replaced(good, "  basis_count: 40", "  basis_count: 41")),
            "model.yaml: model: 40 basis centres/40 widths for N = 41");
  EXPECT_EQ(errorOf(replaced(good, "  alpha: 4", "  alpha: fast")), "model.yaml: parameters.alpha: is not a number");
  EXPECT_EQ(errorOf(replaced(good, "demo_duration:", "duration:")), "model.yaml: demo_duration: missing");
  EXPECT_EQ(errorOf(replaced(good, "scaling: amplitude", "scaling: auto")),
            "model.yaml: joints[4].scaling: 'auto' is not goal or amplitude");
  EXPECT_EQ(errorOf(replaced(good, "weights: [", "weights: [.nan, ")),
            "model.yaml: joints[0].weights: holds a number that is not finite");
  EXPECT_EQ(errorOf(replaced(good, "weights: [", "weights: [0.5, ")),
            "model.yaml: model: weights of joint 'joint_1': 41 values for 40 basis functions");
  EXPECT_EQ(errorOf(replaced(good, "    start: ", "    start: .nan #")),
            "model.yaml: joints[0].start: is not a finite number");
  EXPECT_NE(errorOf("[1, 2").find("model.yaml:"), std::string::npos);
  EXPECT_EQ(errorOf("- 1\n"), "model.yaml: model: expected a YAML mapping (an empty or cut-short file?)");
  EXPECT_THROW(vrrw_dmp::loadDmp("/nonexistent/model.yaml"), DmpError);
}
