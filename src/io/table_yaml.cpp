#include "billiard_shot_planner/io/table_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <optional>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "text_file.hpp"
#include "yaml_configuration_reader.hpp"

namespace billiard_shot_planner
{
namespace
{
bool startsWith(const std::string& text, const std::string& head)
{
  return text.rfind(head, 0) == 0;
}

/// Where a table file keeps a field of the configuration: the table and the ball–ball contact at their own paths,
/// the balls' mass and radius under `balls:`, the cloth's part of `motion:`; nothing of the cue, the strike or the
/// solver.
std::optional<std::string> tableFilePlace(const std::string& path)
{
  static const std::array<const char*, 4> cloth_motion{"motion.sliding_friction", "motion.rolling_friction",
                                                       "motion.rolling_model", "motion.spinning_friction"};
  if (path == "ball_mass")
    return std::string("balls.mass");
  if (path == "ball_radius")
    return std::string("balls.radius");
  if (startsWith(path, "table.") || startsWith(path, "ball_ball."))
    return path;
  for (const char* field : cloth_motion)
    if (path == field)
      return path;
  return std::nullopt;
}

/// A configuration error in the file's own names ("ball_mass" → "balls.mass").
Error inFileTerms(Error error)
{
  if (auto place = tableFilePlace(error.field))
    error.field = *place;
  return error;
}

/// The parts of the configuration a table file gives, checked: its table, its ball–ball contact, the motion's
/// constants and its balls; the cushion's height against the balls only when the file names them (a caller that
/// does not gives its own ball, which is checked where it is used).
Status validateTableFile(const ShotConfiguration& c, bool names_balls)
{
  Status motion = validate(c.motion);
  if (!motion)
  {
    Error error = motion.error();
    error.field = "motion." + error.field;
    motion = error;
  }
  return firstError({validate(c.table, "table"), validate(c.ball_contact.ball_ball, "ball_ball"),
                     requireStiffnessRatio(c.ball_contact.stiffness_ratio, "ball_ball.cloth_stiffness_ratio"), motion,
                     requirePositive(c.ball_mass, "ball_mass"), requirePositive(c.ball_radius, "ball_radius"),
                     names_balls ? validateForBall(c.table, c.ball_radius) : Status{}});
}

TableFile tableFileOf(const ShotConfiguration& configuration)
{
  TableFile file;
  file.table = configuration.table;
  file.ball.mass = configuration.ball_mass;
  file.ball.radius = configuration.ball_radius;
  file.ball_contact = configuration.ball_contact;
  file.motion = configuration.motion;
  return file;
}
}  // namespace

Expected<TableFile> parseTableFile(const std::string& text)
{
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& e)
  {
    return invalidArgument("table", std::string("not valid YAML: ") + e.what());
  }
  if (!root.IsMap() || !root["table"] || !root["table"].IsMap())
    return invalidArgument("table", "the file needs a top-level `table:` map");
  ShotConfiguration configuration;
  yaml_io::YamlConfigurationReader reader(root, configuration.table, tableFilePlace);
  if (Status status = visitConfiguration(configuration, reader); !status)
    return status.error();
  const std::string what = "a field of a table file (docs/cli.md, Table files)";
  if (Status status = yaml_io::onlyVisitedKeys(root, "", reader.visited(), what); !status)
    return status.error();
  const YAML::Node& file = root;  // a const node: looking a key up does not add it
  if (Status status = validateTableFile(configuration, file["balls"].IsDefined()); !status)
    return inFileTerms(status.error());
  return tableFileOf(configuration);
}

Expected<TableFile> loadTableFile(const std::string& path)
{
  auto text = readTextFile(path, "table_file");
  if (!text)
    return text.error();
  return parseTableFile(text.value());
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
