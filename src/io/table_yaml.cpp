#include "billiard_shot_planner/io/table_yaml.hpp"

#include "billiard_shot_planner/core/validation.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace billiard_shot_planner
{
namespace
{
Status readNumber(const YAML::Node& node, const std::string& key, double& target, const std::string& prefix)
{
  if (!node[key])
    return {};
  try
  {
    target = node[key].as<double>();
  }
  catch (const YAML::Exception&)
  {
    return invalidArgument(prefix + key, "must be a number");
  }
  return {};
}

/// `law: {type: elastic_plastic, yield_speed: 1.2}`: the law's type and its parameters, unknown keys refused.
Status readLaw(const YAML::Node& node, const std::string& field, NormalLaw& law)
{
  if (!node.IsMap() || !node["type"] || !node["type"].IsScalar())
    return invalidArgument(field + ".type", "is required: the law is a map {type: <name>, <parameters>}");
  auto chosen = lawOfType(node["type"].Scalar(), field);
  if (!chosen)
    return chosen.error();
  law = chosen.value();
  std::vector<std::string> known = {"type"};
  Status status;
  visitLawParameters(law,
                     [&](const char* name, double& value)
                     {
                       known.emplace_back(name);
                       if (status)
                         status = readNumber(node, name, value, field + ".");
                     });
  if (!status)
    return status;
  for (const auto& item : node)
  {
    const std::string key = item.first.as<std::string>();
    if (std::find(known.begin(), known.end(), key) == known.end())
    {
      std::string message = "is not a parameter of the law \"";
      message += lawType(law);
      message += '"';
      std::string name = field;
      name += '.';
      name += key;
      return invalidArgument(name, message);
    }
  }
  return validate(law, field);
}

Status readSurface(const YAML::Node& node, const std::string& key, SurfaceContact& surface)
{
  if (!node[key])
    return {};
  const std::string prefix = "table." + key + ".";
  return firstError({readNumber(node[key], "restitution", surface.restitution, prefix),
                     readNumber(node[key], "friction", surface.friction, prefix),
                     readNumber(node[key], "eta2", surface.eta2, prefix),
                     node[key]["law"] ? readLaw(node[key]["law"], prefix + "law", surface.normal_law) : Status{}});
}

Expected<std::vector<Pocket>> readPockets(const YAML::Node& list)
{
  if (!list.IsSequence())
    return invalidArgument("table.pockets", "must be a list of {centre: [x, y], radius: r}");
  std::vector<Pocket> pockets;
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const std::string name = "table.pockets[" + std::to_string(i) + "]";
    try
    {
      const auto centre = list[i]["centre"].as<std::vector<double>>();
      if (centre.size() != 2)
        return invalidArgument(name + ".centre", "must be [x, y]");
      pockets.push_back({{centre[0], centre[1]}, list[i]["radius"].as<double>()});
    }
    catch (const YAML::Exception&)
    {
      return invalidArgument(name, "needs centre: [x, y] and radius: r");
    }
  }
  return pockets;
}

Expected<Table> readTable(const YAML::Node& root)
{
  const YAML::Node node = root["table"];
  if (!node || !node.IsMap())
    return invalidArgument("table", "the file needs a top-level `table:` map");
  Table table;
  if (Status status = firstError(
          {readNumber(node, "length", table.length, "table."), readNumber(node, "width", table.width, "table."),
           readNumber(node, "cushion_height", table.cushion_height, "table."),
           readNumber(node, "cushion_stiffness_ratio", table.cushion_stiffness_ratio, "table."),
           readSurface(node, "cloth", table.cloth), readSurface(node, "cushion", table.cushion)});
      !status)
    return status.error();
  table.pockets = sixPockets(table.length, table.width);
  if (node["pockets"])
  {
    auto pockets = readPockets(node["pockets"]);
    if (!pockets)
      return pockets.error();
    table.pockets = pockets.value();
  }
  if (Status status = validate(table); !status)
    return status.error();
  return table;
}
}  // namespace

Expected<Table> parseTableYaml(const std::string& text)
{
  try
  {
    return readTable(YAML::Load(text));
  }
  catch (const YAML::Exception& e)
  {
    return invalidArgument("table", std::string("not valid YAML: ") + e.what());
  }
}

Expected<Table> loadTableYaml(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
    return invalidArgument("table_file", "cannot open " + path);
  std::stringstream text;
  text << file.rdbuf();
  return parseTableYaml(text.str());
}

}  // namespace billiard_shot_planner
