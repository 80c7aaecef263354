#include "billiard_shot_planner/io/table_yaml.hpp"

#include "billiard_shot_planner/core/validation.hpp"

#include <yaml-cpp/yaml.h>

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

Status readSurface(const YAML::Node& node, const std::string& key, SurfaceContact& surface)
{
  if (!node[key])
    return {};
  const std::string prefix = "table." + key + ".";
  return firstError({readNumber(node[key], "restitution", surface.restitution, prefix),
                     readNumber(node[key], "friction", surface.friction, prefix),
                     readNumber(node[key], "eta2", surface.eta2, prefix)});
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
