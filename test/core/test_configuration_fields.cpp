// visitConfiguration: the one list of the configuration's fields. Every number once, a law's type before its
// parameters, choices by name with their options, and the paths that belong to a configuration.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// Every path the walk offers, in order, with the kind of field.
class PathRecorder final : public bsp::ConfigurationVisitor
{
public:
  void number(const std::string& path, double& /*value*/) override { paths.push_back(path); }
  void flag(const std::string& path, bool& /*value*/) override { paths.push_back(path); }
  void choice(const std::string& path, std::string& /*value*/, const std::vector<std::string>& /*options*/) override
  {
    paths.push_back(path);
  }
  void pockets(const std::string& path, std::vector<bsp::Pocket>& /*pockets*/, const bsp::Table& /*table*/) override
  {
    paths.push_back(path);
  }
  std::vector<std::string> paths;
};

std::size_t indexOf(const std::vector<std::string>& paths, const std::string& path)
{
  return static_cast<std::size_t>(std::find(paths.begin(), paths.end(), path) - paths.begin());
}
}  // namespace

TEST(ConfigurationFields, EveryFieldOnceAndLawTypesBeforeTheirParameters)
{
  bsp::ShotConfiguration c;
  c.table.cushion.normal_law = bsp::ElasticPlasticRestitution{};
  PathRecorder recorder;
  ASSERT_TRUE(bsp::visitConfiguration(c, recorder).ok());
  const std::set<std::string> unique(recorder.paths.begin(), recorder.paths.end());
  EXPECT_EQ(unique.size(), recorder.paths.size());
  // 31 numbers of the default laws and 2 x 5 of the pockets' cuts, one law parameter, one flag, 3 + 5 choices and
  // the pockets.
  EXPECT_EQ(recorder.paths.size(), 41u + 1u + 1u + 8u + 1u);
  EXPECT_LT(indexOf(recorder.paths, "table.cushion.law.type"),
            indexOf(recorder.paths, "table.cushion.law.yield_speed"));
  EXPECT_LT(indexOf(recorder.paths, "table.width"), indexOf(recorder.paths, "table.pockets"));
  EXPECT_LT(indexOf(recorder.paths, "table.pocket_layout"), indexOf(recorder.paths, "table.pockets"));
  EXPECT_EQ(bsp::numericParameters(c).size(), 42u);
}

TEST(ConfigurationFields, ChoicesAreSetByNameAndCheckedWhole)
{
  bsp::ShotConfiguration c;
  ASSERT_TRUE(bsp::applyChoice(c, "motion.rolling_model", "pooltool").ok());
  EXPECT_EQ(c.motion.rolling_model, bsp::RollingModel::Pooltool);
  ASSERT_TRUE(bsp::applyChoice(c, "motion.planar", "true").ok());
  EXPECT_TRUE(c.motion.planar);
  ASSERT_TRUE(bsp::applyChoice(c, "table.cushion.law.type", "elastic_plastic").ok());
  EXPECT_TRUE(bsp::applyOverride(c, "table.cushion.law.yield_speed", 1.2).ok());

  const auto wrong = bsp::applyChoice(c, "motion.rolling_model", "leckie");
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.error().field, "motion.rolling_model");
  EXPECT_NE(wrong.error().message.find("\"paper\", \"pooltool\""), std::string::npos) << wrong.error().message;
  EXPECT_EQ(c.motion.rolling_model, bsp::RollingModel::Pooltool);  // unchanged
  EXPECT_EQ(bsp::applyChoice(c, "motion.planar", "yes").error().field, "motion.planar");
  EXPECT_EQ(bsp::applyChoice(c, "table.cloth.friction", "0.2").error().field, "table.cloth.friction");

  bool listed = false;
  for (const bsp::NamedChoice& choice : bsp::configurationChoices(c))
    if (choice.name == "ball_ball.friction_model")
    {
      listed = true;
      EXPECT_EQ(choice.value, "alciatore");
      EXPECT_EQ(choice.options, (std::vector<std::string>{"alciatore", "constant"}));
    }
  EXPECT_TRUE(listed);
}

TEST(ConfigurationFields, PathsOfAConfigurationAndOfOtherInput)
{
  EXPECT_TRUE(bsp::isConfigurationPath("table.cloth.friction"));
  EXPECT_TRUE(bsp::isConfigurationPath("table.pockets[2]"));
  EXPECT_TRUE(bsp::isConfigurationPath("cue_mass"));
  EXPECT_FALSE(bsp::isConfigurationPath("shots[0].tracks.cue[3].t"));
  EXPECT_FALSE(bsp::isConfigurationPath("position_sigma"));
  EXPECT_EQ(bsp::parameterNameOfField("table.cloth.friction"), "table/cloth/friction");
  EXPECT_EQ(bsp::parameterNameOfField("shots[0].tracks.cue"), "shots[0].tracks.cue");
}

TEST(ConfigurationFields, EnumerationsHaveOneSpellingEachWay)
{
  for (auto model : {bsp::RollingModel::Paper, bsp::RollingModel::Pooltool})
    EXPECT_EQ(bsp::rollingModelNamed(bsp::nameOf(model), "m").value(), model);
  for (auto model : {bsp::BallBallFriction::Alciatore, bsp::BallBallFriction::Constant})
    EXPECT_EQ(bsp::ballBallFrictionNamed(bsp::nameOf(model), "m").value(), model);
  EXPECT_EQ(bsp::nameOf(bsp::RollingModel::Pooltool), "pooltool");
  const auto wrong = bsp::rollingModelNamed("leckie", "motion.rolling_model");
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.error().field, "motion.rolling_model");
}
