#include <gtest/gtest.h>

#include "options.h"

using vrrw_dmp::OptionError;
using vrrw_dmp::Options;

namespace
{
Options parse(std::vector<const char*> words)
{
  words.insert(words.begin(), { "vrrw_dmp", "rollout" });
  return Options(static_cast<int>(words.size()), words.data(), 2, { "goal", "tau", "rollout", "basis" });
}

std::string errorOf(std::vector<const char*> words)
{
  try
  {
    parse(words);
  }
  catch (const OptionError& e)
  {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(Options, NegativeValuesParseInBothForms)
{
  EXPECT_EQ(parse({ "--goal=-0.5,1.2,-3e-1" }).numbers("goal"), (std::vector<double>{ -0.5, 1.2, -0.3 }));
  EXPECT_EQ(parse({ "--goal", "-0.5,1.2" }).numbers("goal"), (std::vector<double>{ -0.5, 1.2 }));
  EXPECT_EQ(parse({ "--tau", "-2" }).number("tau", 0.0), -2.0);
  EXPECT_EQ(parse({ "--tau=+2.5" }).number("tau", 0.0), 2.5);
  EXPECT_EQ(parse({}).number("tau", 7.0), 7.0);
  EXPECT_TRUE(parse({}).numbers("goal").empty());
}

TEST(Options, RepeatedKeysAreAllKept)
{
  const Options options = parse({ "--rollout", "a.csv", "--rollout=b.csv" });
  EXPECT_EQ(options.all("rollout"), (std::vector<std::string>{ "a.csv", "b.csv" }));
  EXPECT_EQ(options.text("rollout"), "b.csv");
}

TEST(Options, MistakesAreNamed)
{
  EXPECT_EQ(errorOf({ "--speed", "2" }), "unknown option --speed");
  EXPECT_EQ(errorOf({ "goal" }), "unexpected argument 'goal' (options are --key value or --key=value)");
  EXPECT_EQ(errorOf({ "--tau" }), "--tau needs a value");
  EXPECT_THROW(parse({ "--goal=1,,2" }).numbers("goal"), OptionError);
  try
  {
    parse({ "--goal=1,x" }).numbers("goal");
  }
  catch (const OptionError& e)
  {
    EXPECT_STREQ(e.what(), "--goal value 2: 'x' is not a finite number");
  }
  EXPECT_THROW(parse({ "--goal=1,nan" }).numbers("goal"), OptionError);
  EXPECT_THROW(parse({ "--basis=2.5" }).count("basis", 1), OptionError);
  EXPECT_THROW(parse({ "--basis=-1" }).count("basis", 1), OptionError);
  EXPECT_EQ(parse({ "--basis=0" }).count("basis", 1), 0u);
  EXPECT_THROW(parse({}).text("goal"), OptionError);
}
