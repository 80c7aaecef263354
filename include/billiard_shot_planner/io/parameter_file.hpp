#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/io/table_yaml.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// A parameter file of the node read as a configuration: the file's fields over a starting configuration.
struct ParameterFile
{
  ShotConfiguration configuration;
  /// The file's top-level keys that are no part of the configuration (the node's own settings: target_frame,
  /// planning, …), in the file's order, for the caller to judge.
  std::vector<std::string> other_keys;
};

/// Reads a parameter file in the node's format (config/default.yaml, config/paper_masse.yaml, config/cues/*.yaml,
/// config/table_9ft.yaml) over `base`: every field of the configuration by its path (`table: cloth: friction:`), a
/// law's type before its parameters, pockets as [x, y, radius] or {centre: [x, y], radius}. A field the file leaves
/// out keeps base's value; pockets left out follow a changed table size or layout (defaultPockets). Errors:
/// InvalidArgument naming the field ("table.cloth.friction": a value of the wrong type, out of range;
/// "table.cloth.frition": a key of the configuration's own sections that is none of its fields), or "parameter_file"
/// for text that is not YAML.
Expected<ParameterFile> parseParameterFile(const std::string& text, const ShotConfiguration& base = {});
/// The same from a file (error field "parameter_file" when it cannot be opened).
Expected<ParameterFile> loadParameterFile(const std::string& path, const ShotConfiguration& base = {});

/// The configuration with a table file's table, balls, ball–ball contact and motion in place of its own, as
/// `impact_solve`'s "table_file" applies one.
ShotConfiguration withTableFile(ShotConfiguration configuration, const TableFile& file);

}  // namespace billiard_shot_planner
