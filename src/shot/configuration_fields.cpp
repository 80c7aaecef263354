#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "billiard_shot_planner/core/validation.hpp"

#include <algorithm>
#include <initializer_list>
#include <sstream>
#include <utility>

namespace billiard_shot_planner
{
namespace
{
/// An enumeration's values by the names the configuration gives them.
template <class Enum>
using ChoiceNames = std::vector<std::pair<std::string, Enum>>;

const ChoiceNames<RollingModel>& rollingModels()
{
  static const ChoiceNames<RollingModel> names{{"paper", RollingModel::Paper}, {"pooltool", RollingModel::Pooltool}};
  return names;
}

const ChoiceNames<PocketLayout>& pocketLayouts()
{
  static const ChoiceNames<PocketLayout> names{{"six", PocketLayout::Six}, {"none", PocketLayout::None}};
  return names;
}

const ChoiceNames<PocketModel>& pocketModels()
{
  static const ChoiceNames<PocketModel> names{{"circles", PocketModel::Circles}, {"jaws", PocketModel::Jaws}};
  return names;
}

const ChoiceNames<BallBallFriction>& ballBallFrictionModels()
{
  static const ChoiceNames<BallBallFriction> names{{"alciatore", BallBallFriction::Alciatore},
                                                   {"constant", BallBallFriction::Constant}};
  return names;
}

std::string listed(const std::vector<std::string>& options)
{
  std::string list;
  for (const std::string& option : options)
    list += (list.empty() ? "\"" : ", \"") + option + "\"";
  return list;
}

Status notAnOption(const std::string& path, const std::string& value, const std::vector<std::string>& options)
{
  return invalidArgument(path, "must be one of " + listed(options) + ", got \"" + value + "\"");
}

template <class Enum>
std::string nameIn(const ChoiceNames<Enum>& names, Enum value)
{
  for (const auto& [name, option] : names)
    if (option == value)
      return name;
  return {};
}

template <class Enum>
Expected<Enum> namedIn(const ChoiceNames<Enum>& names, const std::string& name, const std::string& field)
{
  std::vector<std::string> options;
  for (const auto& [known, option] : names)
  {
    if (known == name)
      return option;
    options.push_back(known);
  }
  return notAnOption(field, name, options).error();
}

/// Offers an enumeration to the visitor by name and takes back the name it leaves.
template <class Enum>
Status visitEnum(ConfigurationVisitor& visitor, const std::string& path, const ChoiceNames<Enum>& names, Enum& value)
{
  std::vector<std::string> options;
  std::string current;
  for (const auto& [name, option] : names)
  {
    options.push_back(name);
    if (option == value)
      current = name;
  }
  visitor.choice(path, current, options);
  const auto chosen =
      std::find_if(names.begin(), names.end(), [&](const auto& named) { return named.first == current; });
  if (chosen == names.end())
    return notAnOption(path, current, options);
  value = chosen->second;
  return {};
}

/// A contact's three constants, its law's type and then the law's own parameters (their names follow the type).
Status visitSurface(ConfigurationVisitor& visitor, const std::string& path, SurfaceContact& surface)
{
  visitor.number(path + ".restitution", surface.restitution);
  visitor.number(path + ".friction", surface.friction);
  visitor.number(path + ".eta2", surface.eta2);
  std::string type = lawType(surface.normal_law);
  visitor.choice(path + ".law.type", type, lawTypes());
  if (type != lawType(surface.normal_law))
  {
    auto law = lawOfType(type, path + ".law");
    if (!law)
      return law.error();
    surface.normal_law = law.value();
  }
  visitLawParameters(surface.normal_law,
                     [&](const char* name, double& value) { visitor.number(path + ".law." + name, value); });
  return {};
}

void visitPocketCut(ConfigurationVisitor& visitor, const std::string& path, PocketCut& cut)
{
  visitor.number(path + ".mouth", cut.mouth);
  visitor.number(path + ".facing_angle", cut.facing_angle);
  visitor.number(path + ".shelf", cut.shelf);
  visitor.number(path + ".jaw_radius", cut.jaw_radius);
  visitor.number(path + ".drop_radius", cut.drop_radius);
}

Status visitTable(ConfigurationVisitor& visitor, Table& table)
{
  visitor.number("table.length", table.length);
  visitor.number("table.width", table.width);
  visitor.number("table.cushion_height", table.cushion_height);
  visitor.number("table.cushion_stiffness_ratio", table.cushion_stiffness_ratio);
  if (Status status = firstError(
          {visitSurface(visitor, "table.cloth", table.cloth), visitSurface(visitor, "table.cushion", table.cushion)});
      !status)
    return status;
  if (Status status = firstError({visitEnum(visitor, "table.pocket_layout", pocketLayouts(), table.pocket_layout),
                                  visitEnum(visitor, "table.pocket_model", pocketModels(), table.pocket_model)});
      !status)
    return status;
  visitPocketCut(visitor, "table.corner_pockets", table.corner_pockets);
  visitPocketCut(visitor, "table.side_pockets", table.side_pockets);
  visitor.pockets("table.pockets", table.pockets, table);
  return {};
}

Status visitMotion(ConfigurationVisitor& visitor, MotionParameters& motion)
{
  visitor.number("motion.gravity", motion.gravity);
  visitor.number("motion.sliding_friction", motion.sliding_friction);
  visitor.number("motion.rolling_friction", motion.rolling_friction);
  if (Status status = visitEnum(visitor, "motion.rolling_model", rollingModels(), motion.rolling_model); !status)
    return status;
  visitor.number("motion.spinning_friction", motion.spinning_friction);
  visitor.flag("motion.planar", motion.planar);
  visitor.number("motion.min_bounce_speed", motion.min_bounce_speed);
  visitor.number("motion.max_time", motion.max_time);
  return {};
}

Status visitBallContact(ConfigurationVisitor& visitor, BallContactSettings& contact)
{
  if (Status status = visitSurface(visitor, "ball_ball", contact.ball_ball); !status)
    return status;
  visitor.number("ball_ball.cloth_stiffness_ratio", contact.stiffness_ratio);
  return visitEnum(visitor, "ball_ball.friction_model", ballBallFrictionModels(), contact.friction_model);
}

/// Reads every choice and flag as text; sets the one named, when asked.
class ChoiceAccess final : public ConfigurationVisitor
{
public:
  explicit ChoiceAccess(std::string target = {}, std::string value = {})
      : target_(std::move(target)), value_(std::move(value))
  {
  }

  void number(const std::string& /*path*/, double& /*value*/) override {}
  void flag(const std::string& path, bool& value) override
  {
    if (path == target_)
    {
      found_ = true;
      if (value_ != "true" && value_ != "false")
      {
        bad_flag_ = true;
        return;
      }
      value = value_ == "true";
    }
    choices_.push_back({path, value ? "true" : "false", {"false", "true"}});
  }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& options) override
  {
    if (path == target_)
    {
      found_ = true;
      value = value_;
    }
    choices_.push_back({path, value, options});
  }
  void pockets(const std::string& /*path*/, std::vector<Pocket>& /*pockets*/, const Table& /*table*/) override {}

  const std::vector<NamedChoice>& choices() const { return choices_; }
  bool found() const { return found_; }
  bool badFlag() const { return bad_flag_; }

private:
  std::string target_, value_;
  std::vector<NamedChoice> choices_;
  bool found_ = false;
  bool bad_flag_ = false;
};
}  // namespace

Status visitConfiguration(ShotConfiguration& c, ConfigurationVisitor& visitor)
{
  visitor.number("cue_mass", c.cue_mass);
  visitor.number("cue_end_mass", c.cue_end_mass);
  visitor.number("ball_mass", c.ball_mass);
  visitor.number("ball_radius", c.ball_radius);
  Status status = visitSurface(visitor, "cue_contact", c.cue_contact);
  visitor.number("stiffness_ratio", c.stiffness_ratio);
  // The walk stops at the visitor's first failure or at a choice that is not an option.
  if (status && visitor.status())
    status = visitTable(visitor, c.table);
  if (status && visitor.status())
    status = visitMotion(visitor, c.motion);
  if (status && visitor.status())
  {
    visitor.number("solver.relative_tolerance", c.solver.relative_tolerance);
    visitor.number("solver.absolute_tolerance", c.solver.absolute_tolerance);
    visitor.number("solver.max_seconds", c.solver.max_seconds);
    status = visitBallContact(visitor, c.ball_contact);
  }
  return firstError({visitor.status(), status});
}

std::vector<NamedChoice> configurationChoices(ShotConfiguration configuration)
{
  ChoiceAccess access;
  (void)visitConfiguration(configuration, access);  // reading only: every choice is an option
  return access.choices();
}

Status applyChoice(ShotConfiguration& configuration, const std::string& name, const std::string& value)
{
  ShotConfiguration changed = configuration;
  ChoiceAccess access(name, value);
  Status visited = visitConfiguration(changed, access);
  if (!access.found())
    return invalidArgument(name, "is not a choice of the configuration");
  if (access.badFlag())
    return invalidArgument(name, "must be \"true\" or \"false\", got \"" + value + "\"");
  if (!visited)
    return visited;
  if (Status status = validate(changed); !status)
    return status;
  configuration = changed;
  return {};
}

std::string nameOf(RollingModel model)
{
  return nameIn(rollingModels(), model);
}

std::string nameOf(BallBallFriction model)
{
  return nameIn(ballBallFrictionModels(), model);
}

Expected<RollingModel> rollingModelNamed(const std::string& name, const std::string& field)
{
  return namedIn(rollingModels(), name, field);
}

Expected<BallBallFriction> ballBallFrictionNamed(const std::string& name, const std::string& field)
{
  return namedIn(ballBallFrictionModels(), name, field);
}

std::vector<std::string> pathSteps(const std::string& path)
{
  std::vector<std::string> parts;
  std::stringstream stream(path);
  for (std::string part; std::getline(stream, part, '.');)
    parts.push_back(part);
  return parts;
}

Error unknownField(const std::string& field, const std::string& what)
{
  const std::string law = ".law.";
  const std::size_t at = field.rfind(law);
  if (at != std::string::npos && field.find('.', at + law.size()) == std::string::npos)
    return invalidArgument(field, "is not a parameter of the law that " + field.substr(0, at + law.size()) +
                                      "type chooses (docs/impact_model.md lists the laws)");
  return invalidArgument(field, "is not " + what);
}

std::vector<std::string> configurationFieldPaths()
{
  /// Lists the path of every field the walk offers.
  class PathList final : public ConfigurationVisitor
  {
  public:
    void number(const std::string& path, double& /*value*/) override { paths.push_back(path); }
    void flag(const std::string& path, bool& /*value*/) override { paths.push_back(path); }
    void choice(const std::string& path, std::string& /*value*/, const std::vector<std::string>& /*options*/) override
    {
      paths.push_back(path);
    }
    void pockets(const std::string& path, std::vector<Pocket>& /*pockets*/, const Table& /*table*/) override
    {
      paths.push_back(path);
    }
    std::vector<std::string> paths;
  };
  PathList list;
  ShotConfiguration configuration;
  (void)visitConfiguration(configuration, list);  // listing only: every choice stays an option
  return list.paths;
}

bool isConfigurationPath(const std::string& path)
{
  static const std::vector<std::string> first_steps = []
  {
    std::vector<std::string> steps;
    for (const std::string& field : configurationFieldPaths())
      steps.push_back(field.substr(0, field.find('.')));
    return steps;
  }();
  const std::string first = path.substr(0, path.find_first_of(".["));
  return std::find(first_steps.begin(), first_steps.end(), first) != first_steps.end();
}

}  // namespace billiard_shot_planner
