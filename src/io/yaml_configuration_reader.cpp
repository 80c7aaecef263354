#include "yaml_configuration_reader.hpp"

#include <utility>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
namespace yaml_io
{
namespace
{
/// Descends by fresh nodes: assigning to a YAML::Node would rebind the tree it came from.
YAML::Node at(const YAML::Node& node, const std::vector<std::string>& parts, std::size_t i)
{
  if (i == parts.size())
    return node;
  if (!node.IsMap() || !node[parts[i]])
    return YAML::Node(YAML::NodeType::Undefined);
  return at(node[parts[i]], parts, i + 1);
}

/// One [x, y, radius (, id)] or {(id: name, )centre: [x, y], radius: r}.
Expected<Pocket> pocketOf(const YAML::Node& node, const std::string& field)
{
  try
  {
    if (node.IsSequence() && (node.size() == 3 || node.size() == 4))
      return Pocket{{node[0].as<double>(), node[1].as<double>()},
                    node[2].as<double>(),
                    node.size() == 4 ? node[3].as<std::string>() : std::string()};
    const bool named = node.IsMap() && node["id"];
    if (node.IsMap() && node.size() == (named ? 3U : 2U) && node["centre"] && node["radius"])
    {
      const YAML::Node centre = node["centre"];
      if (!centre.IsSequence() || centre.size() != 2)
        return invalidArgument(field + ".centre", "must be [x, y]");
      Pocket pocket{{centre[0].as<double>(), centre[1].as<double>()}, node["radius"].as<double>(), ""};
      if (named && (!node["id"].IsScalar() || node["id"].Scalar().empty()))
        return invalidArgument(field + ".id", "must be a non-empty name");
      if (named)
        pocket.id = node["id"].Scalar();
      return pocket;
    }
  }
  catch (const YAML::Exception&)
  {
  }
  return invalidArgument(field,
                         "must be [x, y, radius], [x, y, radius, id] or {id: name, centre: [x, y], radius: r} "
                         "(the id optional), in numbers");
}

}  // namespace

YamlConfigurationReader::YamlConfigurationReader(const YAML::Node& root, Table base_table, FieldLocation location)
    : root_(root), base_table_(std::move(base_table)), location_(std::move(location))
{
}

void YamlConfigurationReader::number(const std::string& path, double& value)
{
  read(path, value, "must be a number");
}

void YamlConfigurationReader::flag(const std::string& path, bool& value)
{
  read(path, value, "must be true or false");
}

void YamlConfigurationReader::choice(const std::string& path, std::string& value,
                                     const std::vector<std::string>& /*options*/)
{
  read(path, value, "must be a name");
}

void YamlConfigurationReader::pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table)
{
  const std::optional<std::string> place = location_(path);
  const YAML::Node node = place ? find(*place) : YAML::Node(YAML::NodeType::Undefined);
  if (!node)
  {
    if (!sameDefaultPockets(table, base_table_))
      pockets = defaultPockets(table);
    return;
  }
  if (!node.IsSequence())
    return fail(invalidArgument(*place, "must be a list of pockets"));
  std::vector<Pocket> read;
  for (std::size_t i = 0; i < node.size(); ++i)
  {
    auto pocket = pocketOf(node[i], *place + "[" + std::to_string(i) + "]");
    if (!pocket)
      return fail(pocket.error());
    read.push_back(pocket.value());
  }
  pockets = read;
}

template <class T>
void YamlConfigurationReader::read(const std::string& path, T& value, const char* what)
{
  const std::optional<std::string> place = location_(path);
  if (!place)
    return;
  const YAML::Node node = find(*place);
  if (!node)
    return;
  try
  {
    if (!node.IsScalar())
      return fail(invalidArgument(*place, what));
    value = node.as<T>();
  }
  catch (const YAML::Exception&)
  {
    fail(invalidArgument(*place, what));
  }
}

YAML::Node YamlConfigurationReader::find(const std::string& place)
{
  const std::vector<std::string> parts = pathSteps(place);
  std::string prefix;
  YAML::Node node = root_;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    prefix += (prefix.empty() ? "" : ".") + parts[i];
    visited_.insert(prefix);
    // A section given as something other than a map would hide its fields: refused, not skipped.
    const YAML::Node next = at(node, {parts[i]}, 0);
    if (next && i + 1 < parts.size() && !next.IsMap())
    {
      fail(invalidArgument(prefix, "must be a map"));
      return YAML::Node(YAML::NodeType::Undefined);
    }
    if (!next)
      return next;
    node.reset(next);
  }
  return node;
}

Expected<std::string> keyOf(const YAML::Node& key, const std::string& place)
{
  if (!key.IsScalar())
    return invalidArgument(place.empty() ? "table" : place, "has a key that is a list or a map, not a name");
  if (key.Scalar().find('.') != std::string::npos)
    return invalidArgument(place.empty() ? key.Scalar() : place + "." + key.Scalar(),
                           "is a dotted path, not a name: write each step as its own map");
  return key.Scalar();
}

Status onlyVisitedKeys(const YAML::Node& node, const std::string& place, const std::set<std::string>& visited,
                       const std::string& what)
{
  if (!node.IsMap())
    return {};
  for (const auto& item : node)
  {
    auto key = keyOf(item.first, place);
    if (!key)
      return key.error();
    const std::string name = place.empty() ? key.value() : place + "." + key.value();
    if (!visited.count(name))
      return unknownField(name, what);
    if (Status status = onlyVisitedKeys(item.second, name, visited, what); !status)
      return status;
  }
  return {};
}

}  // namespace yaml_io
}  // namespace billiard_shot_planner
