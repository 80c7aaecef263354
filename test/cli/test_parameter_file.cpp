// The node's parameter files read as a configuration: the shipped default.yaml is the code's default, an overlay
// reads over it, pockets follow a changed size, both pocket formats read, and bad files give named errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "billiard_shot_planner/io/parameter_file.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
std::string config(const std::string& name)
{
  return std::string(CONFIG_DIR) + "/" + name;
}
}  // namespace

TEST(ParameterFile, ShippedDefaultsAreTheCodesDefaultsButTheNodesBudget)
{
  const auto read = bsp::loadParameterFile(config("default.yaml"));
  ASSERT_TRUE(read.ok()) << read.error().describe();
  bsp::ShotConfiguration file = read.value().configuration;
  bsp::ShotConfiguration code;
  const auto from_file = bsp::numericParameters(file);
  const auto from_code = bsp::numericParameters(code);
  ASSERT_EQ(from_file.size(), from_code.size());
  int compared = 0;
  for (std::size_t i = 0; i < from_file.size(); ++i)
  {
    ASSERT_EQ(from_file[i].name, from_code[i].name);
    // The node answers a robot within a second; the library's own budget is a batch's (docs/python.md).
    if (from_file[i].name == "solver.max_seconds")
      continue;
    EXPECT_EQ(*from_file[i].value, *from_code[i].value) << from_file[i].name;
    ++compared;
  }
  EXPECT_GE(compared, 30);
  EXPECT_EQ(file.table.pockets.size(), 6u);
  // The node's own settings are handed back, not read.
  const auto& others = read.value().other_keys;
  for (const char* key : {"target_frame", "tf_timeout", "planning", "cockpit"})
    EXPECT_NE(std::find(others.begin(), others.end(), key), others.end()) << key;
}

TEST(ParameterFile, AnOverlayReadsOverTheFirstFile)
{
  const auto defaults = bsp::loadParameterFile(config("default.yaml"));
  ASSERT_TRUE(defaults.ok());
  const auto masse = bsp::loadParameterFile(config("paper_masse.yaml"), defaults.value().configuration);
  ASSERT_TRUE(masse.ok()) << masse.error().describe();
  const bsp::ShotConfiguration& c = masse.value().configuration;
  EXPECT_TRUE(std::isinf(c.cue_end_mass));  // paper_masse.yaml: cue_end_mass: .inf
  EXPECT_EQ(c.cue_contact.eta2, 7.0);
  EXPECT_TRUE(c.motion.planar);
  EXPECT_EQ(c.ball_contact.ball_ball.restitution, 0.95);  // default.yaml's, which the overlay leaves
}

TEST(ParameterFile, ChoicesLawsAndPockets)
{
  const auto read = bsp::parseParameterFile(R"(
table:
  length: 2.24
  width: 1.12
  cushion: {law: {type: elastic_plastic, yield_speed: 1.5}}
motion: {rolling_model: pooltool}
ball_ball: {friction_model: constant}
)");
  ASSERT_TRUE(read.ok()) << read.error().describe();
  const bsp::ShotConfiguration& c = read.value().configuration;
  EXPECT_EQ(c.motion.rolling_model, bsp::RollingModel::Pooltool);
  EXPECT_EQ(c.ball_contact.friction_model, bsp::BallBallFriction::Constant);
  ASSERT_TRUE(std::holds_alternative<bsp::ElasticPlasticRestitution>(c.table.cushion.normal_law));
  // The 8-ft table's corner pocket sits on its own corner: the pockets follow the size the file gives.
  EXPECT_DOUBLE_EQ(c.table.pockets[3].centre.x(), 1.12);
  EXPECT_DOUBLE_EQ(c.table.pockets[3].centre.y(), 0.56);

  const auto listed =
      bsp::parseParameterFile("table: {pockets: [[1.0, 0.5, 0.05], {centre: [0.0, 0.6], radius: 0.07}]}");
  ASSERT_TRUE(listed.ok()) << listed.error().describe();
  ASSERT_EQ(listed.value().configuration.table.pockets.size(), 2u);
  EXPECT_EQ(listed.value().configuration.table.pockets[1].radius, 0.07);
  EXPECT_TRUE(bsp::parseParameterFile("").ok());
}

TEST(ParameterFile, BadFilesNameTheField)
{
  const std::pair<const char*, const char*> cases[] = {
      {"table: {cloth: {frition: 0.2}}", "table.cloth.frition"},
      {"table: {cloth: {friction: fast}}", "table.cloth.friction"},
      {"table: {cloth: {friction: -1}}", "table.cloth.friction"},
      {"motion: {rolling_model: leckie}", "motion.rolling_model"},
      {"motion: {planar: maybe}", "motion.planar"},
      {"table: {cushion: {law: {type: hertz}}}", "table.cushion.law.type"},
      {"table: {cushion: {law: {yield_speed: 1.0}}}", "table.cushion.law.yield_speed"},
      {"table: {pockets: [[0, 0]]}", "table.pockets[0]"},
      {"table: {pockets: 3}", "table.pockets"},
      {"cue_mass: [1, 2]", "cue_mass"},
      {"table: 5", "table"},  // a section that is not a map would hide its fields
      {"table: {cushion: {law: elastic_plastic}}", "table.cushion.law"},
      {"? [1, 2]\n: 3", "parameter_file"},  // a key that is a list
      {"table: {cloth: {? [1] : 2}}", "table.cloth"},
      {"table: [", "parameter_file"},
      {"- 1", "parameter_file"},
  };
  for (const auto& [text, field] : cases)
  {
    const auto read = bsp::parseParameterFile(text);
    ASSERT_FALSE(read.ok()) << text;
    EXPECT_EQ(read.error().field, field) << text << ": " << read.error().describe();
  }
  EXPECT_EQ(bsp::loadParameterFile("/no/such/file.yaml").error().field, "parameter_file");
  // A top-level key of no section is handed back for the caller to judge (the node's settings are such keys).
  const auto other = bsp::parseParameterFile("ball_mas: 0.2");
  ASSERT_TRUE(other.ok());
  EXPECT_EQ(other.value().other_keys, std::vector<std::string>{"ball_mas"});
}
