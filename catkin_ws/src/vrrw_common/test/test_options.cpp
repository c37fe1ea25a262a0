#include <gtest/gtest.h>
#include <vrrw_common/options.h>

using vrrw_common::OptionError;
using vrrw_common::Options;
using vrrw_common::Range;

namespace
{
/// `tool send WORDS...` with the keys of a typical tool.
Options parse(std::vector<const char*> words)
{
  words.insert(words.begin(), { "tool", "send" });
  return Options(static_cast<int>(words.size()), words.data(), 2,
                 { "duration", "trials", "joints", "mode", "out", "seed", "csv", "gripper" }, { "yes", "quick" });
}

/// The one line a mistake gives, or "no error".
template <class Read>
std::string errorOf(std::vector<const char*> words, Read read)
{
  try
  {
    read(parse(words));
  }
  catch (const OptionError& e)
  {
    return e.what();
  }
  return "no error";
}

std::string errorOf(std::vector<const char*> words)
{
  return errorOf(words, [](const Options&) {});
}
}  // namespace

TEST(Options, ReadsBothFormsFlagsAndPositionalWords)
{
  const Options o = parse({ "ur5e", "--joints", "-0.5,1.2,-3e-1", "--mode=physics", "--yes", "b.bag" });
  EXPECT_EQ(o.positional(), (std::vector<std::string>{ "ur5e", "b.bag" }));
  EXPECT_EQ(o.list("joints"), (std::vector<double>{ -0.5, 1.2, -0.3 }));
  EXPECT_EQ(o.choice("mode", { "fake", "physics" }), "physics");
  EXPECT_TRUE(o.flag("yes"));
  EXPECT_FALSE(o.flag("quick"));
  EXPECT_EQ(o.number("duration", 7.0), 7.0);
  EXPECT_EQ(o.count("trials", 20, 1, 1000), 20u);
  EXPECT_EQ(o.text("out", "report"), "report");
  EXPECT_TRUE(o.list("gripper").empty());
  EXPECT_NO_THROW(o.expectPositional({ "ROBOT", "BAG" }));
}

TEST(Options, ALaterValueWinsAndAllAreKept)
{
  const Options o = parse({ "--trials", "3", "--trials=5" });
  EXPECT_EQ(o.count("trials", 1, 1000), 5u);
  EXPECT_EQ(o.all("trials"), (std::vector<std::string>{ "3", "5" }));
}

TEST(Options, ParsingMistakesNameTheOption)
{
  EXPECT_EQ(errorOf({ "--trials" }), "--trials: needs a value");
  EXPECT_EQ(errorOf({ "--trials", "--quick" }), "--trials: needs a value");
  EXPECT_EQ(errorOf({ "--out=" }), "--out: needs a value");
  EXPECT_EQ(errorOf({ "--out", "" }), "--out: needs a value");
  EXPECT_EQ(errorOf({ "--speed", "2" }), "unknown option --speed");
  EXPECT_EQ(errorOf({ "--yes=1" }), "--yes: takes no value");
  EXPECT_EQ(errorOf({ "--" }), "unexpected argument '--'");
  EXPECT_EQ(errorOf({ "a" }, [](const Options& o) { o.expectPositional({ "ROBOT", "BAG" }); }), "missing BAG");
  EXPECT_EQ(errorOf({ "a", "b" }, [](const Options& o) { o.expectPositional({ "ROBOT" }); }),
            "unexpected argument 'b'");
  EXPECT_EQ(errorOf({}, [](const Options& o) { o.text("csv"); }), "--csv: required");
}

TEST(Options, NumbersAreFiniteAndInRange)
{
  const auto duration = [](const Options& o) { o.number("duration", 0.0, Range::aboveUpTo(0, 86400, "s")); };
  EXPECT_EQ(errorOf({ "--duration", "1e10" }, duration), "--duration: 1e10 outside (0, 86400] s");
  EXPECT_EQ(errorOf({ "--duration", "0" }, duration), "--duration: 0 outside (0, 86400] s");
  EXPECT_EQ(errorOf({ "--duration", "inf" }, duration), "--duration: 'inf' is not a finite number");
  EXPECT_EQ(errorOf({ "--duration", "nan" }, duration), "--duration: 'nan' is not a finite number");
  EXPECT_EQ(errorOf({ "--duration", "2s" }, duration), "--duration: '2s' is not a number");
  EXPECT_EQ(errorOf({ "--duration", "86400" }, duration), "no error");
  EXPECT_EQ(parse({ "--duration=+2.5" }).number("duration"), 2.5);
  const auto closed = [](const Options& o) { o.number("gripper", Range::closed(0, 0.085, "m")); };
  EXPECT_EQ(errorOf({ "--gripper", "-1" }, closed), "--gripper: -1 outside [0, 0.085] m");
}

TEST(Options, AnEchoIsCutToAFewDozenCharacters)
{
  const std::string huge(100000, '7');
  const std::string error = errorOf({ "--duration", (huge + "x").c_str() }, [](const Options& o) { o.number("duration"); });
  EXPECT_EQ(error, "--duration: '" + std::string(40, '7') + "...' is not a number");
}

TEST(Options, CountsAreWholeNumbersAtLeastTheirLowerBound)
{
  const auto trials = [](const Options& o) { o.count("trials", 1, 1000); };
  EXPECT_EQ(errorOf({ "--trials", "-1" }, trials), "--trials: -1 is not a whole number >= 1");
  EXPECT_EQ(errorOf({ "--trials", "0" }, trials), "--trials: 0 is not a whole number >= 1");
  EXPECT_EQ(errorOf({ "--trials", "2.5" }, trials), "--trials: 2.5 is not a whole number >= 1");
  EXPECT_EQ(errorOf({ "--trials", "x" }, trials), "--trials: 'x' is not a whole number >= 1");
  EXPECT_EQ(errorOf({ "--trials", "1001" }, trials), "--trials: 1001 outside [1, 1000]");
  const auto seed = [](const Options& o) { o.count("seed", 0, Options::kMaxCount); };
  EXPECT_EQ(errorOf({ "--seed", "-1" }, seed), "--seed: -1 is not a whole number >= 0");
  EXPECT_EQ(errorOf({ "--seed", "1e30" }, seed), "--seed: 1e30 outside [0, 9007199254740992]");
  EXPECT_EQ(parse({ "--seed", "4711" }).count("seed", 0, Options::kMaxCount), 4711u);
  EXPECT_EQ(parse({ "--seed", "1e3" }).count("seed", 0, Options::kMaxCount), 1000u);
  EXPECT_EQ(parse({ "--seed", "18446744073709551615" }).count("seed", 0, UINT64_MAX), UINT64_MAX);
  EXPECT_EQ(errorOf({ "--seed", "18446744073709551616" }, [](const Options& o) { o.count("seed", 0, UINT64_MAX); }),
            "--seed: 18446744073709551616 outside [0, 18446744073709551615]");
  EXPECT_EQ(errorOf({ "--seed", "9007199254740993" }, seed), "--seed: 9007199254740993 outside [0, 9007199254740992]");
}

TEST(Options, ListsHaveTheirLengthAndEveryValueChecked)
{
  const auto joints = [](const Options& o) { o.list("joints", 6); };
  EXPECT_EQ(errorOf({ "--joints", "1,2,3,4,5" }, joints), "--joints: 5 values, expected 6");
  EXPECT_EQ(errorOf({ "--joints", "1" }, joints), "--joints: 1 value, expected 6");
  EXPECT_EQ(errorOf({ "--joints", "1,,3,4,5,6" }, joints), "--joints value 2: '' is not a number");
  EXPECT_EQ(errorOf({ "--joints", "1,2,3,4,5,inf" }, joints), "--joints value 6: 'inf' is not a finite number");
  EXPECT_EQ(errorOf({ "--joints", "1,2,3,4,5,7" }, [](const Options& o) { o.list("joints", 6, Range::closed(-6.3, 6.3)); }),
            "--joints value 6: 7 outside [-6.3, 6.3]");
  EXPECT_EQ(parse({ "--joints=0,0,0,0,0,1e-3" }).list("joints", 6).back(), 1e-3);
}

TEST(Options, ChoicesAndExclusiveOptions)
{
  const auto mode = [](const Options& o) { o.choice("mode", { "fake", "physics", "real" }); };
  EXPECT_EQ(errorOf({ "--mode", "x" }, mode), "--mode: 'x' is not one of fake, physics, real");
  EXPECT_EQ(parse({}).choice("mode", "fake", { "fake", "physics" }), "fake");
  const auto what = [](const Options& o) { o.oneOf({ "csv", "joints", "gripper" }); };
  EXPECT_EQ(errorOf({}, what), "give one of --csv, --joints, --gripper");
  EXPECT_EQ(errorOf({ "--csv", "a", "--gripper", "0" }, what), "--csv and --gripper exclude each other");
  EXPECT_EQ(parse({ "--joints", "0" }).oneOf({ "csv", "joints", "gripper" }), "joints");
}
