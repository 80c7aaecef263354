#pragma once

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"

namespace billiard_shot_planner
{
/// Everything a table file gives (config/tables/snooker_mathavan.yaml): the table, and optionally its balls
/// (`balls:`), the ball–ball contact (`ball_ball:`) and the balls' motion on its cloth (`motion:`). What a file
/// leaves out keeps the defaults.
struct TableFile
{
  Table table;
  BallProperties ball;
  BallContactSettings ball_contact;
  MotionParameters motion;
};

/// Reads a table file from YAML text. Unknown keys are refused, as are values out of range; the error names the
/// field ("table.cushion.law.yield_speed", "ball_ball.friction_model").
Expected<TableFile> parseTableFile(const std::string& text);
/// The same from a file (error field "table_file" when it cannot be opened).
Expected<TableFile> loadTableFile(const std::string& path);

/// Reads a table from YAML text in the format of config/table_9ft.yaml (a top-level `table:` map). Fields that
/// are absent keep the defaults of Table; pockets default to defaultPockets() for the given size and layout. The
/// error names the field.
Expected<Table> parseTableYaml(const std::string& text);

/// The same from a file.
Expected<Table> loadTableYaml(const std::string& path);

}  // namespace billiard_shot_planner
