#include "json_configuration_reader.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "billiard_shot_planner/io/parameter_file.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
bool startsWith(const std::string& text, const std::string& head)
{
  return text.rfind(head, 0) == 0;
}

/// One pocket: {"centre": [x, y], "radius": r}, with an optional "id".
Expected<Pocket> pocketOf(const json& item, const std::string& field)
{
  if (!item.is_object())
    return invalidArgument(field, "must be an object");
  if (Status known = onlyKnownKeys(item, {"id", "centre", "radius"}, field); !known)
    return known.error();
  auto centre = numbers(item, "centre");
  if (!centre)
    return nested(field, centre.error());
  if (centre.value().size() != 2)
    return invalidArgument(field + ".centre", "must be [x, y]");
  auto radius = number(item, "radius");
  if (!radius)
    return nested(field, radius.error());
  Pocket pocket{{centre.value()[0], centre.value()[1]}, radius.value(), ""};
  if (item.contains("id"))
  {
    if (!item["id"].is_string() || item["id"].get<std::string>().empty())
      return invalidArgument(field + ".id", "must be a non-empty string");
    pocket.id = item["id"].get<std::string>();
  }
  return pocket;
}

/// Reads each field the request has from its place, remembering the places it looked at.
class JsonConfigurationReader final : public ConfigurationVisitor
{
public:
  JsonConfigurationReader(const json& request, Table base_table) : request_(request), base_table_(std::move(base_table))
  {
  }

  void number(const std::string& path, double& value) override
  {
    const auto [place, node] = find(path);
    if (!node)
      return;
    if (path == "cue_end_mass" && *node == "inf")
    {
      value = CUE_HELD_ON_AXIS;
      return;
    }
    if (!node->is_number())
      return fail(
          invalidArgument(place, path == "cue_end_mass" ? "must be a number of kg or \"inf\"" : "must be a number"));
    value = node->get<double>();
  }

  void flag(const std::string& path, bool& value) override
  {
    const auto [place, node] = find(path);
    if (!node)
      return;
    if (!node->is_boolean())
      return fail(invalidArgument(place, "must be true or false"));
    value = node->get<bool>();
  }

  /// A name that is not an option is left for visitConfiguration to refuse, listing the options.
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& options) override
  {
    const auto [place, node] = find(path);
    if (!node)
      return;
    if (!node->is_string())
    {
      std::string names;
      for (const std::string& option : options)
        names += (names.empty() ? "\"" : ", \"") + option + "\"";
      return fail(invalidArgument(place, "must be one of " + names));
    }
    value = node->get<std::string>();
  }

  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table) override
  {
    const auto [place, node] = find(path);
    if (!node)
    {
      if (!sameDefaultPockets(table, base_table_))
        pockets = defaultPockets(table);
      return;
    }
    if (!node->is_array())
      return fail(invalidArgument(place, "must be an array of {\"centre\": [x, y], \"radius\": r}"));
    std::vector<Pocket> read;
    for (std::size_t i = 0; i < node->size(); ++i)
    {
      auto pocket = pocketOf(node->at(i), place + "[" + std::to_string(i) + "]");
      if (!pocket)
        return fail(pocket.error());
      read.push_back(pocket.value());
    }
    pockets = read;
  }

  const std::set<std::string>& visited() const { return visited_; }

private:
  /// The field's place in the request and its value there (none when the request leaves it out). A section that is
  /// not an object ("table": 3) is refused: it would hide its fields.
  std::pair<std::string, const json*> find(const std::string& path)
  {
    const std::optional<std::string> place = requestPlace(path);
    if (!place)
      return {std::string(), nullptr};
    const json* node = &request_;
    std::string prefix;
    const std::vector<std::string> parts = pathSteps(*place);
    for (std::size_t i = 0; i < parts.size(); ++i)
    {
      prefix += (prefix.empty() ? "" : ".") + parts[i];
      visited_.insert(prefix);
      if (!node->contains(parts[i]))
        return {*place, nullptr};
      node = &node->at(parts[i]);
      if (i + 1 < parts.size() && !node->is_object())
      {
        fail(invalidArgument(prefix, "must be an object"));
        return {*place, nullptr};
      }
    }
    return {*place, node};
  }

  const json& request_;
  const Table base_table_;
  std::set<std::string> visited_;
};

/// The first key inside `node` (at `place`) that the reader did not look at.
Status onlyVisitedKeys(const json& node, const std::string& place, const std::set<std::string>& visited)
{
  if (!node.is_object())
    return {};
  for (const auto& item : node.items())
  {
    const std::string name = place + "." + item.key();
    if (item.key().find('.') != std::string::npos)
      return invalidArgument(name, "is not a field here: a key is a name, not a dotted path");
    if (!visited.count(name))
      return unknownField(name, "a field here");
    if (Status status = onlyVisitedKeys(item.value(), name, visited); !status)
      return status;
  }
  return {};
}

/// The request's objects that hold fields of the configuration ("table", "cue_contact", "ball_ball"): the first
/// steps of the places that have more than one.
std::vector<std::string> requestSections()
{
  std::vector<std::string> sections;
  for (const std::string& path : configurationFieldPaths())
    if (const std::optional<std::string> place = requestPlace(path); place && place->find('.') != std::string::npos)
    {
      const std::string first = pathSteps(*place).front();
      if (std::find(sections.begin(), sections.end(), first) == sections.end())
        sections.push_back(first);
    }
  return sections;
}

/// The configuration a request starts from: the defaults, a table file's table, contacts and motion (its balls are
/// for library callers: a request gives its own ball), or the strike's cloth as the table's.
Expected<ShotConfiguration> requestBase(const json& request)
{
  ShotConfiguration base;
  if (request.contains("table_file"))
  {
    auto file = tableFile(request);
    if (!file)
      return file.error();
    base = withTableFile(base, file.value());
    base.ball_mass = ShotConfiguration{}.ball_mass;
    base.ball_radius = ShotConfiguration{}.ball_radius;
  }
  else if (request.contains("table_contact"))
  {
    auto cloth = strikeCloth(request, base);
    if (!cloth)
      return cloth.error();
    base.table.cloth = cloth.value();
  }
  return base;
}
}  // namespace

std::optional<std::string> requestPlace(const std::string& path)
{
  if (startsWith(path, "solver."))
    return std::nullopt;
  if (startsWith(path, "motion."))
    return path.substr(std::string("motion.").size());
  return path;
}

std::vector<std::string> requestFieldsOf(const std::vector<ConfigurationPart>& parts)
{
  const auto in_part = [](const std::string& path, ConfigurationPart part)
  {
    const bool ball = path == "ball_mass" || path == "ball_radius";
    switch (part)
    {
      case ConfigurationPart::Strike:
        return ball || startsWith(path, "table.cloth.") ||
               !(startsWith(path, "table.") || startsWith(path, "motion.") || startsWith(path, "ball_ball.") ||
                 startsWith(path, "solver."));
      case ConfigurationPart::Motion:
        return ball || startsWith(path, "table.") || startsWith(path, "motion.");
      case ConfigurationPart::BallContact:
        return startsWith(path, "ball_ball.");
    }
    return false;
  };
  std::vector<std::string> fields;
  if (!parts.empty())
    fields.emplace_back("table_file");
  const auto add = [&fields](const std::string& field)
  {
    if (std::find(fields.begin(), fields.end(), field) == fields.end())
      fields.push_back(field);
  };
  for (ConfigurationPart part : parts)
  {
    if (part == ConfigurationPart::Strike)
      add("table_contact");
    for (const std::string& path : configurationFieldPaths())
      if (const std::optional<std::string> place = requestPlace(path); place && in_part(path, part))
        add(pathSteps(*place).front());
  }
  return fields;
}

Error inRequestLayout(Error error)
{
  if (startsWith(error.field, "motion."))
    error.field = error.field.substr(std::string("motion.").size());
  return error;
}

Expected<ShotConfiguration> requestConfiguration(const json& request)
{
  auto base = requestBase(request);
  if (!base)
    return base.error();
  if (Status status = checkFrictionModel(request.value("ball_ball", json::object())); !status)
    return status.error();
  ShotConfiguration configuration = base.value();
  JsonConfigurationReader reader(request, configuration.table);
  if (Status status = visitConfiguration(configuration, reader); !status)
    return inRequestLayout(status.error());
  static const std::vector<std::string> sections = requestSections();
  for (const std::string& section : sections)
    if (request.contains(section))
      if (Status status = onlyVisitedKeys(request.at(section), section, reader.visited()); !status)
        return status.error();
  const json ball_ball = request.value("ball_ball", json::object());
  if (ball_ball.contains("friction") && !ball_ball.contains("friction_model"))
    configuration.ball_contact.friction_model = BallBallFriction::Constant;
  return configuration;
}

Expected<SurfaceContact> strikeCloth(const json& request, const ShotConfiguration& configuration)
{
  if (!request.contains("table_contact"))
    return configuration.table.cloth;
  if (!request.at("table_contact").is_object())
    return invalidArgument("table_contact", "must be an object");
  // Its constants one by one over the table file's cloth, or over the default cloth (docs/cli.md, cue_strike).
  SurfaceContact cloth = ShotConfiguration{}.table.cloth;
  if (request.contains("table_file"))
  {
    auto file = tableFile(request);
    if (!file)
      return file.error();
    cloth = file.value().table.cloth;
  }
  if (Status status = readSurfaceContact(request.at("table_contact"), "table_contact", cloth); !status)
    return status.error();
  return cloth;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
