#include "billiard_shot_planner/io/table_yaml.hpp"

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

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

/// Refuses a key of `node` (a map) that `known` does not list: a misspelt constant is an error, not a default.
Status onlyKnownKeys(const YAML::Node& node, std::initializer_list<const char*> known, const std::string& prefix)
{
  if (!node.IsMap())
    return invalidArgument(prefix.empty() ? "table" : prefix.substr(0, prefix.size() - 1), "must be a map");
  for (const auto& item : node)
  {
    const std::string key = item.first.as<std::string>();
    if (std::none_of(known.begin(), known.end(), [&](const char* name) { return key == name; }))
    {
      std::string name = prefix;
      name += key;
      return invalidArgument(name, "is not a field of a table file (docs/cli.md, Table files)");
    }
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
  Status status;
  visitLawParameters(law,
                     [&](const char* name, double& value)
                     {
                       if (status)
                         status = readNumber(node, name, value, field + ".");
                     });
  if (!status)
    return status;
  for (const auto& item : node)
    if (Status key = requireLawKey(law, item.first.as<std::string>(), field); !key)
      return key;
  return validate(law, field);
}

Status readSurface(const YAML::Node& node, const std::string& key, SurfaceContact& surface,
                   const std::string& parent = "table.")
{
  if (!node[key])
    return {};
  const std::string prefix = parent + key + ".";
  return firstError({onlyKnownKeys(node[key], {"restitution", "friction", "eta2", "law"}, prefix),
                     readNumber(node[key], "restitution", surface.restitution, prefix),
                     readNumber(node[key], "friction", surface.friction, prefix),
                     readNumber(node[key], "eta2", surface.eta2, prefix),
                     node[key]["law"] ? readLaw(node[key]["law"], prefix + "law", surface.normal_law) : Status{}});
}

/// A choice by name (`named`: the configuration's own names and their check); absent keeps `value`.
template <class Choice, class Named>
Status readChoice(const YAML::Node& node, const std::string& key, const Named& named, Choice& value,
                  const std::string& prefix)
{
  if (!node[key])
    return {};
  auto chosen = named(node[key].IsScalar() ? node[key].Scalar() : "", prefix + key);
  if (!chosen)
    return chosen.error();
  value = chosen.value();
  return {};
}

/// `balls: {mass, radius}`.
Status readBalls(const YAML::Node& root, BallProperties& ball)
{
  const YAML::Node node = root["balls"];
  if (!node)
    return {};
  return firstError({onlyKnownKeys(node, {"mass", "radius"}, "balls."), readNumber(node, "mass", ball.mass, "balls."),
                     readNumber(node, "radius", ball.radius, "balls."), requirePositive(ball.mass, "balls.mass"),
                     requirePositive(ball.radius, "balls.radius")});
}

/// `ball_ball: {restitution, friction_model, friction, eta2, cloth_stiffness_ratio, law}`, as the node's parameters.
Status readBallContact(const YAML::Node& root, BallContactSettings& contact)
{
  const YAML::Node node = root["ball_ball"];
  if (!node)
    return {};
  return firstError(
      {onlyKnownKeys(node, {"restitution", "friction", "friction_model", "eta2", "cloth_stiffness_ratio", "law"},
                     "ball_ball."),
       readNumber(node, "restitution", contact.ball_ball.restitution, "ball_ball."),
       readNumber(node, "friction", contact.ball_ball.friction, "ball_ball."),
       readNumber(node, "eta2", contact.ball_ball.eta2, "ball_ball."),
       readNumber(node, "cloth_stiffness_ratio", contact.stiffness_ratio, "ball_ball."),
       readChoice(node, "friction_model", ballBallFrictionNamed, contact.friction_model, "ball_ball."),
       node["law"] ? readLaw(node["law"], "ball_ball.law", contact.ball_ball.normal_law) : Status{},
       validate(contact.ball_ball, "ball_ball"),
       requirePositive(contact.stiffness_ratio, "ball_ball.cloth_stiffness_ratio")});
}

/// `motion: {sliding_friction, rolling_friction, rolling_model, spinning_friction}`: the balls on the cloth.
Status readMotion(const YAML::Node& root, MotionParameters& motion)
{
  const YAML::Node node = root["motion"];
  if (!node)
    return {};
  return firstError(
      {onlyKnownKeys(node, {"sliding_friction", "rolling_friction", "rolling_model", "spinning_friction"}, "motion."),
       readNumber(node, "sliding_friction", motion.sliding_friction, "motion."),
       readNumber(node, "rolling_friction", motion.rolling_friction, "motion."),
       readNumber(node, "spinning_friction", motion.spinning_friction, "motion."),
       readChoice(node, "rolling_model", rollingModelNamed, motion.rolling_model, "motion."),
       requirePositive(motion.sliding_friction, "motion.sliding_friction"),
       requirePositive(motion.rolling_friction, "motion.rolling_friction"),
       requirePositive(motion.spinning_friction, "motion.spinning_friction")});
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
          {onlyKnownKeys(
               node, {"length", "width", "cushion_height", "cushion_stiffness_ratio", "cloth", "cushion", "pockets"},
               "table."),
           readNumber(node, "length", table.length, "table."), readNumber(node, "width", table.width, "table."),
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

Expected<TableFile> parseTableFile(const std::string& text)
{
  try
  {
    const YAML::Node root = YAML::Load(text);
    if (!root.IsMap())
      return invalidArgument("table", "the file needs a top-level `table:` map");
    TableFile file;
    auto table = readTable(root);
    if (!table)
      return table.error();
    if (Status status = onlyKnownKeys(root, {"table", "balls", "ball_ball", "motion"}, ""); !status)
      return status.error();
    file.table = table.value();
    if (Status status = firstError(
            {readBalls(root, file.ball), readBallContact(root, file.ball_contact), readMotion(root, file.motion)});
        !status)
      return status.error();
    return file;
  }
  catch (const YAML::Exception& e)
  {
    return invalidArgument("table", std::string("not valid YAML: ") + e.what());
  }
}

Expected<TableFile> loadTableFile(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
    return invalidArgument("table_file", "cannot open " + path);
  std::stringstream text;
  text << file.rdbuf();
  return parseTableFile(text.str());
}

Expected<Table> parseTableYaml(const std::string& text)
{
  auto file = parseTableFile(text);
  if (!file)
    return file.error();
  return file.value().table;
}

Expected<Table> loadTableYaml(const std::string& path)
{
  auto file = loadTableFile(path);
  if (!file)
    return file.error();
  return file.value().table;
}

}  // namespace billiard_shot_planner
