#pragma once

// Reads a ShotConfiguration's fields from a YAML tree by the one list of fields (visitConfiguration): the node's
// parameter files and the table files are two layouts of it (yaml_configuration_reader.cpp).
#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace yaml_io
{
/// Where a layout keeps a field of the configuration: its path in the file ("ball_mass" → "balls.mass"), or none
/// when the layout has no such field.
using FieldLocation = std::function<std::optional<std::string>(const std::string& configuration_path)>;

/// Reads each field the layout has from the YAML node at its place, remembering the places it looked at. Pockets are
/// [x, y, radius] or {centre: [x, y], radius: r}; pockets left out follow a table size or pocket layout
/// that differs from `base_table`'s (defaultPockets).
class YamlConfigurationReader final : public ConfigurationVisitor
{
public:
  YamlConfigurationReader(const YAML::Node& root, Table base_table, FieldLocation location);

  void number(const std::string& path, double& value) override;
  void flag(const std::string& path, bool& value) override;
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& options) override;
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table) override;

  /// The places in the file the walk looked at, with their sections ("table", "table.cloth", "table.cloth.friction").
  const std::set<std::string>& visited() const { return visited_; }

private:
  template <class T>
  void read(const std::string& path, T& value, const char* what);
  YAML::Node find(const std::string& place);

  const YAML::Node root_;
  const Table base_table_;
  const FieldLocation location_;
  std::set<std::string> visited_;
};

/// A map's key as a name; a key that is a list or a map (YAML allows them) is refused naming the map's place ("table"
/// at a table file's top level), one that holds a '.' (it would read as a path) naming itself.
Expected<std::string> keyOf(const YAML::Node& key, const std::string& place);

/// The first key under `node` (at `place`, a map; "" for the file's top level) that the reader did not look at: a
/// misspelt constant is an error, not a default. A key under a law ("table.cushion.law.yield_speed") that the chosen
/// law lacks says so.
Status onlyVisitedKeys(const YAML::Node& node, const std::string& place, const std::set<std::string>& visited,
                       const std::string& what);

}  // namespace yaml_io
}  // namespace billiard_shot_planner
