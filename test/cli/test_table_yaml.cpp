// The table YAML format: the shipped 9-ft table is the code's default, and bad files give named errors.
#include <gtest/gtest.h>

#include "billiard_shot_planner/io/parameter_file.hpp"
#include "billiard_shot_planner/io/table_yaml.hpp"
#include "billiard_shot_planner/motion/table_outline.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace bsp = billiard_shot_planner;

TEST(TableYaml, ShippedNineFootTableEqualsTheDefaults)
{
  const auto loaded = bsp::loadTableYaml(std::string(CONFIG_DIR) + "/table_9ft.yaml");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const bsp::Table& t = loaded.value();
  const bsp::Table d;
  EXPECT_EQ(t.length, d.length);
  EXPECT_EQ(t.width, d.width);
  EXPECT_EQ(t.cushion_height, d.cushion_height);
  EXPECT_EQ(t.cushion_stiffness_ratio, d.cushion_stiffness_ratio);
  EXPECT_EQ(t.cloth.restitution, d.cloth.restitution);
  EXPECT_EQ(t.cloth.friction, d.cloth.friction);
  EXPECT_EQ(t.cloth.eta2, d.cloth.eta2);
  EXPECT_EQ(t.cushion.restitution, d.cushion.restitution);
  EXPECT_EQ(t.cushion.friction, d.cushion.friction);
  EXPECT_EQ(t.cushion.eta2, d.cushion.eta2);
  ASSERT_EQ(t.pockets.size(), d.pockets.size());
  for (std::size_t i = 0; i < t.pockets.size(); ++i)
  {
    EXPECT_EQ(t.pockets[i].centre, d.pockets[i].centre) << i;
    EXPECT_EQ(t.pockets[i].radius, d.pockets[i].radius) << i;
    EXPECT_EQ(t.pockets[i].id, d.pockets[i].id) << i;
  }
}

// A capture circle's id: its own from a map or a list, else its place; the six defaults carry the outline's ids, so a
// pocket is named alike under either pocket model; one id twice is refused naming the second.
TEST(TableYaml, PocketsCarryIdsAndOneIdNamesOnePocket)
{
  const bsp::Table defaults;
  const bsp::TableOutline outline = bsp::tableOutline(defaults).value();
  for (const bsp::Pocket& circle : defaults.pockets)
  {
    // The opening whose mouth is nearest the capture circle's centre has its id.
    const bsp::PocketOpening* nearest = &outline.pockets.front();
    for (const bsp::PocketOpening& opening : outline.pockets)
      if ((opening.mouthMiddle() - circle.centre).norm() < (nearest->mouthMiddle() - circle.centre).norm())
        nearest = &opening;
    EXPECT_EQ(nearest->id, circle.id);
  }
  const auto named = bsp::parseTableYaml(
      "table: {pockets: [{id: far, centre: [1.27, 0.635], radius: 0.06}, [-1.27, 0.635, 0.06, near], [0, 0.635, "
      "0.065]]}");
  ASSERT_TRUE(named.ok()) << named.error().describe();
  EXPECT_EQ(bsp::pocketId(named.value().pockets, 0), "far");
  EXPECT_EQ(bsp::pocketId(named.value().pockets, 1), "near");
  EXPECT_EQ(bsp::pocketId(named.value().pockets, 2), "pocket2");
  EXPECT_EQ(bsp::pocketIndex(named.value().pockets, "near"), 1);
  EXPECT_EQ(bsp::pocketIndex(named.value().pockets, "top_right"), -1);
  EXPECT_EQ(bsp::parseTableYaml("table: {pockets: [[1.27, 0.635, 0.06, a], [-1.27, 0.635, 0.06, a]]}").error().field,
            "table.pockets[1].id");
  EXPECT_EQ(bsp::parseTableYaml("table: {pockets: [[1.27, 0.635, 0.06, pocket1], [-1.27, 0.635, 0.06]]}").error().field,
            "table.pockets[1].id");
  EXPECT_EQ(bsp::parseTableYaml("table: {pockets: [{id: '', centre: [1.27, 0.635], radius: 0.06}]}").error().field,
            "table.pockets[0].id");
}

TEST(TableYaml, PartialFilesKeepDefaultsAndBadOnesNameTheField)
{
  const auto small = bsp::parseTableYaml("table: {length: 2.24, width: 1.12}");
  ASSERT_TRUE(small.ok());
  EXPECT_EQ(small.value().pockets.size(), 6u);
  EXPECT_DOUBLE_EQ(small.value().pockets[3].centre.x(), 1.12);
  EXPECT_EQ(bsp::parseTableYaml("table: {length: -1}").error().field, "table.length");
  EXPECT_EQ(bsp::parseTableYaml("table: {cushion: {friction: abc}}").error().field, "table.cushion.friction");
  EXPECT_EQ(bsp::parseTableYaml("table: {pockets: [{centre: [0, 0, 1], radius: 0.1}]}").error().field,
            "table.pockets[0].centre");
  EXPECT_EQ(bsp::parseTableYaml("length: 3").error().field, "table");
  EXPECT_EQ(bsp::parseTableYaml("table: [unclosed").error().field, "table");
  EXPECT_EQ(bsp::loadTableYaml("/nonexistent.yaml").error().field, "table_file");
}

TEST(TableYaml, AContactsLawIsReadByTypeWithItsParameters)
{
  const auto snooker = bsp::loadTableYaml(std::string(CONFIG_DIR) + "/tables/snooker_mathavan.yaml");
  ASSERT_TRUE(snooker.ok()) << snooker.error().describe();
  const auto* law = std::get_if<bsp::ElasticPlasticRestitution>(&snooker.value().cushion.normal_law);
  ASSERT_NE(law, nullptr);
  EXPECT_GT(law->yield_speed, 0.0);
  EXPECT_TRUE(std::holds_alternative<bsp::ConstantRestitution>(snooker.value().cloth.normal_law));

  EXPECT_EQ(bsp::parseTableYaml("table: {cushion: {law: {type: hertz_typo}}}").error().field, "table.cushion.law.type");
  // A law's parameter under the default law (constant), which has none: the parameter is named.
  EXPECT_EQ(bsp::parseTableYaml("table: {cushion: {law: {yield_speed: 1}}}").error().field,
            "table.cushion.law.yield_speed");
  EXPECT_EQ(bsp::parseTableYaml("table: {cloth: {law: {type: elastic_plastic, yield_speed: 0}}}").error().field,
            "table.cloth.law.yield_speed");
  EXPECT_EQ(bsp::parseTableYaml("table: {cloth: {law: {type: elastic_plastic, yeild_speed: 1}}}").error().field,
            "table.cloth.law.yeild_speed");
}

TEST(TableYaml, AFileGivesItsBallsContactAndMotionAndRefusesUnknownFields)
{
  const auto snooker = bsp::loadTableFile(std::string(CONFIG_DIR) + "/tables/snooker_mathavan.yaml");
  ASSERT_TRUE(snooker.ok()) << snooker.error().describe();
  EXPECT_EQ(snooker.value().ball.mass, 0.1406);  // the papers' snooker balls
  EXPECT_EQ(snooker.value().ball.radius, 0.02625);
  EXPECT_EQ(snooker.value().ball_contact.friction_model, bsp::BallBallFriction::Constant);
  EXPECT_EQ(snooker.value().motion.sliding_friction, 0.212);

  const std::pair<const char*, const char*> bad[] = {
      {"table: {lenght: 3}", "table.lenght"},
      {"table: {}\nballs: {mass: 0.2, colour: red}", "balls.colour"},
      {"table: {}\nball_ball: {friction_model: magic}", "ball_ball.friction_model"},
      {"table: {}\nball_ball: {restitution: 2}", "ball_ball.restitution"},
      {"table: {}\nmotion: {sliding_friction: -1}", "motion.sliding_friction"},
      {"table: {}\ncue: {}", "cue"},
      {"table: {cushion: {restitution: 0.8, frition: 0.1}}", "table.cushion.frition"},
      {"table: {}\nballs: {radius: -0.03}", "balls.radius"},
      {"table: {}\nballs: 0.17", "balls"},
      {"table: {}\nmotion: {gravity: 9.81}", "motion.gravity"},  // the cloth's part of the motion only
      {"table: {}\ncue_mass: 0.5", "cue_mass"},
      {"table: {}\nball_ball: {law: {type: elastic_plastic, yield_speed: -1}}", "ball_ball.law.yield_speed"},
      {"table:\n  ? [1, 2]\n  : 3", "table"},  // a key that is a list: YAML allows it, a table file does not
      {"table: {cloth: {? {a: 1} : 2}}", "table.cloth"},
      {"table: {cloth: {}, cloth.friction: 0.5}", "table.cloth.friction"},               // a key is a name, not a path
      {"table: {cushion_height: 0.06}\nballs: {radius: 0.02}", "table.cushion_height"},  // above the balls named
  };
  for (const auto& [text, field] : bad)
  {
    const auto file = bsp::parseTableFile(text);
    ASSERT_FALSE(file.ok()) << text;
    EXPECT_EQ(file.error().field, field) << text;
  }
  // A file that names no balls is not held to the default ball: the caller's own is checked where it is used.
  EXPECT_TRUE(bsp::parseTableFile("table: {cushion_height: 0.06}").ok());
}

// A table file and a parameter file are two layouts of the one list of configuration fields: the same constants
// written in each give the same configuration.
TEST(TableYaml, ATableFileReadsAsTheSameFieldsInAParameterFile)
{
  const std::string table =
      "table: {length: 2.84, width: 1.42, cushion: {restitution: 0.8, law: {type: "
      "elastic_plastic, yield_speed: 1.5}}, pockets: [[0, 0.71, 0.06], [0, -0.71, 0.06]]}\n"
      "ball_ball: {restitution: 0.93, friction_model: constant, friction: 0.06}\n"
      "motion: {rolling_model: pooltool, rolling_friction: 0.012}\n";
  const auto file = bsp::parseTableFile(table + "balls: {mass: 0.16, radius: 0.0285}\n");
  const auto parameters = bsp::parseParameterFile(table + "ball_mass: 0.16\nball_radius: 0.0285\n");
  ASSERT_TRUE(file.ok()) << file.error().describe();
  ASSERT_TRUE(parameters.ok()) << parameters.error().describe();
  bsp::ShotConfiguration from_parameters = parameters.value().configuration;
  bsp::ShotConfiguration from_table_file = bsp::withTableFile(bsp::ShotConfiguration{}, file.value());
  const std::vector<bsp::NamedParameter> expected = bsp::numericParameters(from_parameters);
  const std::vector<bsp::NamedParameter> read = bsp::numericParameters(from_table_file);
  ASSERT_EQ(read.size(), expected.size());
  for (std::size_t i = 0; i < read.size(); ++i)
    EXPECT_EQ(*read[i].value, *expected[i].value) << read[i].name;
  EXPECT_EQ(from_table_file.motion.rolling_model, bsp::RollingModel::Pooltool);
  EXPECT_EQ(from_table_file.ball_contact.friction_model, bsp::BallBallFriction::Constant);
  ASSERT_EQ(from_table_file.table.pockets.size(), 2u);
  EXPECT_EQ(from_table_file.table.pockets[1].centre.y(), -0.71);
  EXPECT_EQ(from_table_file.ball_mass, 0.16);
}

namespace
{
bsp::TableFile shippedTable(const std::string& name)
{
  const auto loaded = bsp::loadTableFile(std::string(CONFIG_DIR) + "/tables/" + name);
  if (!loaded)
    throw std::runtime_error(name + ": " + loaded.error().describe());
  return loaded.value();
}
}  // namespace

TEST(TableYaml, TheShippedPoolTablesAreTheWpaSizesWithItsPockets)
{
  constexpr double INCH = 0.0254;
  const std::vector<std::tuple<std::string, double, double>> sizes{
      {"pool_7ft.yaml", 78.0, 39.0}, {"pool_8ft.yaml", 92.0, 46.0}, {"pool_9ft.yaml", 100.0, 50.0}};
  for (const auto& [name, length, width] : sizes)
  {
    const bsp::Table table = shippedTable(name).table;
    EXPECT_NEAR(table.length, length * INCH, 1e-12) << name;
    EXPECT_NEAR(table.width, width * INCH, 1e-12) << name;
    // WPA: the nose at 62.5-64.5 % of the 2.25 in ball, corner mouths 4.5-4.625 in, side 5-5.125 in.
    EXPECT_GE(table.cushion_height, 0.625 * 2.25 * INCH) << name;
    EXPECT_LE(table.cushion_height, 0.645 * 2.25 * INCH) << name;
    EXPECT_GE(table.corner_pockets.mouth, 4.5 * INCH) << name;
    EXPECT_LE(table.corner_pockets.mouth, 4.625 * INCH) << name;
    EXPECT_GE(table.side_pockets.mouth, 5.0 * INCH) << name;
    EXPECT_LE(table.side_pockets.mouth, 5.125 * INCH) << name;
    const auto geometry = bsp::tableOutline(table);
    ASSERT_TRUE(geometry.ok()) << name << ": " << geometry.error().describe();
    EXPECT_EQ(geometry.value().pockets.size(), 6u) << name;
    // The capture regions follow the size: the corner ones on the corners.
    ASSERT_EQ(table.pockets.size(), 6u) << name;
    EXPECT_NEAR(std::abs(table.pockets[0].centre.x()), 0.5 * table.length, 1e-12) << name;
  }
  // The 9-ft file states the defaults.
  const bsp::Table nine = shippedTable("pool_9ft.yaml").table, defaults;
  EXPECT_EQ(nine.length, defaults.length);
  EXPECT_EQ(nine.cushion_height, defaults.cushion_height);
  for (const auto& [read, given] :
       {std::pair{nine.corner_pockets, defaults.corner_pockets}, std::pair{nine.side_pockets, defaults.side_pockets}})
  {
    EXPECT_EQ(read.mouth, given.mouth);
    EXPECT_EQ(read.facing_angle, given.facing_angle);
    EXPECT_EQ(read.shelf, given.shelf);
    EXPECT_EQ(read.jaw_radius, given.jaw_radius);
    EXPECT_EQ(read.drop_radius, given.drop_radius);
  }
}

TEST(TableYaml, TheShippedSnookerAndCaromTablesAreTheirGoverningBodiesSizes)
{
  const bsp::TableFile snooker = shippedTable("snooker_12ft.yaml");
  EXPECT_EQ(snooker.table.length, 3.569);  // WPBSA: 3569 x 1778 mm, balls 52.5 mm
  EXPECT_EQ(snooker.table.width, 1.778);
  EXPECT_EQ(snooker.ball.radius, 0.02625);
  const auto snooker_geometry = bsp::tableOutline(snooker.table);
  ASSERT_TRUE(snooker_geometry.ok()) << snooker_geometry.error().describe();
  EXPECT_EQ(snooker_geometry.value().pockets.size(), 6u);

  const bsp::TableFile carom = shippedTable("carom_10ft.yaml");
  EXPECT_EQ(carom.table.length, 2.84);  // UMB: 2840 x 1420 mm, balls 61-61.5 mm, nose 37 mm
  EXPECT_EQ(carom.table.width, 1.42);
  EXPECT_EQ(carom.table.cushion_height, 0.037);
  EXPECT_EQ(carom.table.pocket_layout, bsp::PocketLayout::None);
  EXPECT_TRUE(carom.table.pockets.empty());
  const auto carom_geometry = bsp::tableOutline(carom.table);
  ASSERT_TRUE(carom_geometry.ok()) << carom_geometry.error().describe();
  EXPECT_TRUE(carom_geometry.value().pockets.empty());
  EXPECT_EQ(carom_geometry.value().cushions.size(), 4u);
}

TEST(TableYaml, APocketCutOutOfRangeOrALayoutNotKnownNamesTheField)
{
  const auto angle = bsp::parseTableYaml("table: {corner_pockets: {facing_angle: 30}}");
  ASSERT_FALSE(angle.ok());
  EXPECT_EQ(angle.error().field, "table.corner_pockets.facing_angle");
  const auto layout = bsp::parseTableYaml("table: {pocket_layout: eight}");
  ASSERT_FALSE(layout.ok());
  EXPECT_EQ(layout.error().field, "table.pocket_layout");
  const auto model = bsp::parseTableYaml("table: {pocket_model: holes}");
  ASSERT_FALSE(model.ok());
  EXPECT_EQ(model.error().field, "table.pocket_model");
  const auto jaws = bsp::parseTableYaml("table: {pocket_model: jaws}");
  ASSERT_TRUE(jaws.ok()) << jaws.error().describe();
  EXPECT_EQ(jaws.value().pocket_model, bsp::PocketModel::Jaws);
  // A table without pockets lays no capture regions, and refuses listed ones.
  const auto carom = bsp::parseTableYaml("table: {pocket_layout: none}");
  ASSERT_TRUE(carom.ok()) << carom.error().describe();
  EXPECT_TRUE(carom.value().pockets.empty());
  const auto contradiction = bsp::parseTableYaml("table: {pocket_layout: none, pockets: [[0, 0, 0.05]]}");
  ASSERT_FALSE(contradiction.ok());
  EXPECT_EQ(contradiction.error().field, "table.pockets");
}
