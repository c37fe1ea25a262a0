#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_yaml.h>

#include "skill_fixture.h"

using vrrw_skills::fromYaml;
using vrrw_skills::SkillError;
using vrrw_skills::toYaml;

namespace
{
std::string errorOf(const std::string& text)
{
  try
  {
    fromYaml(text, "skill.yaml");
  }
  catch (const SkillError& e)
  {
    return e.what();
  }
  return "no error";
}

std::string replaced(std::string text, const std::string& what, const std::string& with)
{
  const auto at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return at == std::string::npos ? text : text.replace(at, what.size(), with);
}
}  // namespace

TEST(SkillYaml, RoundTripIsBitForBit)
{
  const std::string text = toYaml(vrrw_skills_test::pickAndPlace());
  const vrrw_skills::Skill loaded = fromYaml(text, "skill.yaml");
  EXPECT_EQ(toYaml(loaded), text);
  EXPECT_EQ(toYaml(fromYaml(toYaml(loaded), "again.yaml")), text);
  // and the loaded DMPs roll out exactly as the learned ones
  const vrrw_skills::Skill skill = vrrw_skills_test::pickAndPlace();
  vrrw_dmp::RolloutRequest request;
  request.goal = skill.instructions[0].joints_end;
  request.goal[0] += 0.05;
  const auto a = skill.instructions[0].joint_dmp->rollout(request);
  const auto b = loaded.instructions[0].joint_dmp->rollout(request);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k)
    EXPECT_EQ(a.points[k].positions, b.points[k].positions);
  const auto c = skill.instructions[4].cartesian_dmp->rollout({});
  const auto d = loaded.instructions[4].cartesian_dmp->rollout({});
  ASSERT_EQ(c.size(), d.size());
  for (std::size_t k = 0; k < c.size(); ++k)
    EXPECT_EQ(c[k].pose.orientation.coeffs(), d[k].pose.orientation.coeffs());
  EXPECT_EQ(loaded.grasp().frame, vrrw_skills::Frame::object);
  EXPECT_EQ(loaded.sources.front().segments.size(), 2u);
}

TEST(SkillYaml, BadFilesAreOneLineNamingTheField)
{
  const std::string text = toYaml(vrrw_skills_test::pickAndPlace());
  // cut short in the middle of a flow list
  const std::string cut = errorOf(text.substr(0, text.find("weights") + 20));
  EXPECT_EQ(cut.rfind("skill.yaml:", 0), 0u) << cut;
  EXPECT_NE(cut.find("cut short"), std::string::npos) << cut;
  // cut short at a line end: a mapping without the rest
  const std::string truncated = errorOf(text.substr(0, text.find("  - name: pick\n")));
  EXPECT_EQ(truncated, "skill.yaml: sources: missing") << truncated;
  EXPECT_EQ(errorOf(replaced(text, "format: vrrw_skills/1", "format: vrrw_skills/2")),
            "skill.yaml: format: 'vrrw_skills/2' is not 'vrrw_skills/1' (a skill of another version)");
  const std::string unknown = errorOf(replaced(text, "in_hand:\n    position", "in_hand:\n    scale: 1\n    position"));
  EXPECT_EQ(unknown, "no error");  // a field of no meaning here is left alone
  std::string skewed = text;
  const auto end = skewed.find("orientation: [", skewed.find("  end:"));
  skewed.replace(skewed.find('[', end) + 1, 1, "2");
  const std::string norm = errorOf(skewed);
  EXPECT_EQ(norm.rfind("skill.yaml: object.end.orientation: norm ", 0), 0u) << norm;
  EXPECT_NE(norm.find("is not 1 (a unit quaternion x, y, z, w is needed)"), std::string::npos) << norm;
  EXPECT_EQ(errorOf(replaced(text, "frame: object", "frame: table")),
            "skill.yaml: instructions[0].end.frame: 'table' is not world, object or place");
  EXPECT_EQ(errorOf(replaced(text, "kind: gripper", "kind: hand")),
            "skill.yaml: instructions[2].kind: 'hand' is not arm or gripper");
  EXPECT_EQ(errorOf(""), "skill.yaml: skill: expected a YAML mapping (an empty or cut-short file?)");
  const std::string dmp = errorOf(replaced(text, "basis_count: 30", "basis_count: -3"));
  EXPECT_EQ(dmp.rfind("skill.yaml: instructions[0].joint_dmp.parameters.basis_count: ", 0), 0u) << dmp;
}

TEST(SkillYaml, SaveRefusesAnExistingFileAndLoadNamesAMissingOne)
{
  const std::string path = ::testing::TempDir() + "skill_yaml_test.yaml";
  std::remove(path.c_str());
  vrrw_skills::saveSkill(vrrw_skills_test::pickAndPlace(), path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), toYaml(vrrw_skills_test::pickAndPlace()));
  try
  {
    vrrw_skills::saveSkill(vrrw_skills_test::pickAndPlace(), path);
    ADD_FAILURE() << "overwrote " << path;
  }
  catch (const SkillError& e)
  {
    EXPECT_EQ(std::string(e.what()), path + ": exists; not overwritten (remove it or choose another name)");
  }
  std::remove(path.c_str());
  try
  {
    vrrw_skills::loadSkill(path);
    ADD_FAILURE() << "loaded a missing file";
  }
  catch (const SkillError& e)
  {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open for reading (no such file?)");
  }
}
