#include "billiard_shot_planner/io/parameter_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
std::vector<std::string> steps(const std::string& path)
{
  std::vector<std::string> parts;
  std::stringstream stream(path);
  for (std::string part; std::getline(stream, part, '.');)
    parts.push_back(part);
  return parts;
}

/// One [x, y, radius] or {centre: [x, y], radius: r}.
Expected<Pocket> pocketOf(const YAML::Node& node, const std::string& field)
{
  try
  {
    if (node.IsSequence() && node.size() == 3)
      return Pocket{{node[0].as<double>(), node[1].as<double>()}, node[2].as<double>()};
    if (node.IsMap() && node.size() == 2 && node["centre"] && node["radius"] && node["centre"].IsSequence() &&
        node["centre"].size() == 2)
      return Pocket{{node["centre"][0].as<double>(), node["centre"][1].as<double>()}, node["radius"].as<double>()};
  }
  catch (const YAML::Exception&)
  {
  }
  return invalidArgument(field, "must be [x, y, radius] or {centre: [x, y], radius: r}, in numbers");
}

/// Reads each field of the configuration from the YAML node at its path, remembering the paths it looked at.
class YamlReader final : public ConfigurationVisitor
{
public:
  YamlReader(const YAML::Node& root, const Table& base_table) : root_(root), base_table_(base_table) {}

  void number(const std::string& path, double& value) override { read(path, value, "must be a number"); }
  void flag(const std::string& path, bool& value) override { read(path, value, "must be true or false"); }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& /*options*/) override
  {
    read(path, value, "must be a name");
  }
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table) override
  {
    const YAML::Node node = find(path);
    if (!node)
    {
      if (table.length != base_table_.length || table.width != base_table_.width)
        pockets = sixPockets(table.length, table.width);
      return;
    }
    if (!node.IsSequence())
      return fail(invalidArgument(path, "must be a list of pockets"));
    std::vector<Pocket> read;
    for (std::size_t i = 0; i < node.size(); ++i)
    {
      auto pocket = pocketOf(node[i], path + "[" + std::to_string(i) + "]");
      if (!pocket)
        return fail(pocket.error());
      read.push_back(pocket.value());
    }
    pockets = read;
  }
  const std::set<std::string>& visited() const { return visited_; }

private:
  template <class T>
  void read(const std::string& path, T& value, const char* what)
  {
    const YAML::Node node = find(path);
    if (!node)
      return;
    try
    {
      if (!node.IsScalar())
        return fail(invalidArgument(path, what));
      value = node.as<T>();
    }
    catch (const YAML::Exception&)
    {
      fail(invalidArgument(path, what));
    }
  }

  /// The node at `path`, or an undefined node; the path and its sections count as known.
  YAML::Node find(const std::string& path)
  {
    const std::vector<std::string> parts = steps(path);
    std::string prefix;
    for (const std::string& part : parts)
      visited_.insert(prefix += (prefix.empty() ? "" : ".") + part);
    return at(root_, parts, 0);
  }

  /// Descends by fresh nodes: assigning to a YAML::Node would rebind the tree it came from.
  static YAML::Node at(const YAML::Node& node, const std::vector<std::string>& parts, std::size_t i)
  {
    if (i == parts.size())
      return node;
    if (!node.IsMap() || !node[parts[i]])
      return YAML::Node(YAML::NodeType::Undefined);
    return at(node[parts[i]], parts, i + 1);
  }

  const YAML::Node root_;
  const Table base_table_;
  std::set<std::string> visited_;
};

/// The first key under `node` (at `path`) that no field of the configuration has.
Status onlyKnownKeys(const YAML::Node& node, const std::string& path, const std::set<std::string>& known)
{
  if (!node.IsMap())
    return {};
  for (const auto& item : node)
  {
    const std::string name = path + "." + item.first.as<std::string>();
    if (!known.count(name))
      return invalidArgument(name, "is not a parameter of the configuration (config/default.yaml lists them)");
    if (Status status = onlyKnownKeys(item.second, name, known); !status)
      return status;
  }
  return {};
}
}  // namespace

Expected<ParameterFile> parseParameterFile(const std::string& text, const ShotConfiguration& base)
{
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& e)
  {
    return invalidArgument("parameter_file", std::string("is not YAML: ") + e.what());
  }
  if (root.IsNull())
    return ParameterFile{base, {}};
  if (!root.IsMap())
    return invalidArgument("parameter_file", "must be a map of parameters");
  ParameterFile file{base, {}};
  YamlReader reader(root, base.table);
  if (Status status = visitConfiguration(file.configuration, reader); !status)
    return status.error();
  for (const auto& item : root)
  {
    const std::string key = item.first.as<std::string>();
    if (!reader.visited().count(key))
      file.other_keys.push_back(key);
    else if (Status status = onlyKnownKeys(item.second, key, reader.visited()); !status)
      return status.error();
  }
  if (Status status = validate(file.configuration); !status)
    return status.error();
  return file;
}

Expected<ParameterFile> loadParameterFile(const std::string& path, const ShotConfiguration& base)
{
  std::ifstream file(path);
  if (!file)
    return invalidArgument("parameter_file", "cannot open " + path);
  std::stringstream text;
  text << file.rdbuf();
  return parseParameterFile(text.str(), base);
}

ShotConfiguration withTableFile(ShotConfiguration configuration, const TableFile& file)
{
  configuration.table = file.table;
  configuration.ball_mass = file.ball.mass;
  configuration.ball_radius = file.ball.radius;
  configuration.ball_contact = file.ball_contact;
  configuration.motion = file.motion;
  return configuration;
}

}  // namespace billiard_shot_planner
