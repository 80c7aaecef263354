#include "billiard_shot_planner/io/parameter_file.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>

#include "billiard_shot_planner/core/validation.hpp"
#include "text_file.hpp"
#include "yaml_configuration_reader.hpp"

namespace billiard_shot_planner
{
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
  // A parameter file keeps every field at its own path.
  yaml_io::YamlConfigurationReader reader(root, base.table,
                                          [](const std::string& path) { return std::optional<std::string>(path); });
  if (Status status = visitConfiguration(file.configuration, reader); !status)
    return status.error();
  for (const auto& item : root)
  {
    auto named = yaml_io::keyOf(item.first, "parameter_file");
    if (!named)
      return named.error();
    const std::string& key = named.value();
    if (!reader.visited().count(key))
      file.other_keys.push_back(key);
    else if (Status status =
                 yaml_io::onlyVisitedKeys(item.second, key, reader.visited(),
                                          "a parameter of the configuration (config/default.yaml lists them)");
             !status)
      return status.error();
  }
  if (Status status = validate(file.configuration); !status)
    return status.error();
  return file;
}

Expected<ParameterFile> loadParameterFile(const std::string& path, const ShotConfiguration& base)
{
  auto text = readTextFile(path, "parameter_file");
  if (!text)
    return text.error();
  return parseParameterFile(text.value(), base);
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
