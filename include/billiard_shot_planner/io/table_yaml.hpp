#pragma once

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table.hpp"

namespace billiard_shot_planner
{
/// Reads a table from YAML text in the format of config/table_9ft.yaml (a top-level `table:` map). Fields that
/// are absent keep the defaults of Table; pockets default to sixPockets() for the given length and width. The
/// error names the field.
Expected<Table> parseTableYaml(const std::string& text);

/// The same from a file.
Expected<Table> loadTableYaml(const std::string& path);

}  // namespace billiard_shot_planner
