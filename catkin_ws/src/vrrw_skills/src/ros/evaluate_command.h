#pragma once
// `skill evaluate SKILL.yaml --scene SCENE [--robot R] [--object NAME] [--trials N] [--seed S]
// [--spread DX,DY,DYAW_DEG] [--out DIR]`: headless, a master and a physics workspace of its own.
namespace vrrw_skills
{
/// \brief Checks every input first (nothing is started or written for a bad one), then runs the trials and
/// writes DIR/metrics.json, DIR/index.html, DIR/top_view.png. Returns the exit code; bad input throws.
int evaluateCommand(int argc, char** argv);
}  // namespace vrrw_skills
