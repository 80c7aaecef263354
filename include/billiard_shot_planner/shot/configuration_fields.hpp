#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// What a front end does with each field of a ShotConfiguration: read it from a file or a parameter server, list
/// it, set it by name (the pattern of Drake's `Serialize(Archive*)`). visitConfiguration walks the fields once, in
/// one order, so a new field is declared there and every front end (ROS parameters, YAML, Python) follows.
/// A visitor that fails keeps its own first error and returns it from `status()`; the walk then stops with it.
class ConfigurationVisitor
{
public:
  virtual ~ConfigurationVisitor() = default;
  /// A number at `path` ("table.cloth.friction"); the visitor may change it (visitConfiguration validates after).
  virtual void number(const std::string& path, double& value) = 0;
  /// A yes or no ("motion.planar").
  virtual void flag(const std::string& path, bool& value) = 0;
  /// One of `options` by name ("motion.rolling_model": "paper" or "pooltool"); `value` holds the current one. A
  /// visitor that sets it to a name not among the options makes visitConfiguration fail naming `path`.
  virtual void choice(const std::string& path, std::string& value, const std::vector<std::string>& options) = 0;
  /// The table's pockets ("table.pockets"), after the table's size: a reader that finds none may lay the default
  /// ones out for the size and layout it read (defaultPockets).
  virtual void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table) = 0;
  /// The visitor's first error, once it has failed: the walk stops and returns it.
  Status status() const { return first_error_; }

protected:
  /// Keeps the first failure a visitor meets (the later ones follow from it); success changes nothing.
  void fail(Status status)
  {
    if (first_error_ && !status)
      first_error_ = std::move(status);
  }

private:
  Status first_error_;
};

/// Calls the visitor for every field of the configuration: the numbers (numericParameters' names), the flags, the
/// choices — each contact's law type ("table.cushion.law.type") before that law's own parameters, whose names
/// follow the type — and the pockets. Errors: the visitor's own first one (status()), or a choice set to a name that is
/// not an option (InvalidArgument naming the path and listing the options). The configuration is not validated
/// here (validate()).
Status visitConfiguration(ShotConfiguration& configuration, ConfigurationVisitor& visitor);

/// The choices of the configuration and their options, by path: motion.rolling_model, ball_ball.friction_model,
/// and each contact's law type.
struct NamedChoice
{
  std::string name;
  std::string value;
  std::vector<std::string> options;
};
std::vector<NamedChoice> configurationChoices(ShotConfiguration configuration);

/// Sets the choice or flag `name` ("motion.rolling_model", "motion.planar": "true"/"false") to `value` on a copy and
/// keeps it when the configuration stays valid. Errors: an unknown name, a value that is not an option.
Status applyChoice(ShotConfiguration& configuration, const std::string& name, const std::string& value);

/// The names the configuration gives the rolling models ("paper", "pooltool") and the ball–ball friction models
/// ("alciatore", "constant"), and back: the one place they are spelt. Errors name `field` and list the names.
std::string nameOf(RollingModel model);
std::string nameOf(BallBallFriction model);
Expected<RollingModel> rollingModelNamed(const std::string& name, const std::string& field);
Expected<BallBallFriction> ballBallFrictionNamed(const std::string& name, const std::string& field);

/// "table.cloth.friction" → "table/cloth/friction": a field's path as the parameters' name, which the ROS node and
/// the Python API share (each front end maps the core's paths to its own names at its boundary).
inline std::string parameterName(std::string path)
{
  std::replace(path.begin(), path.end(), '.', '/');
  return path;
}

/// The path of every field of the configuration, in the walk's order, with the default law's parameters (a law's
/// type decides which parameters follow it).
std::vector<std::string> configurationFieldPaths();

/// Whether `path` lies in a configuration ("table.cloth.friction", "table.pockets[2]") rather than in a call's other
/// input ("shots[0].tracks.cue[3].t"): its first step is one of the configuration's.
bool isConfigurationPath(const std::string& path);

/// A call's error field as the parameters name it: a configuration path with '/' ("table/cloth/friction"), any
/// other field as it is.
inline std::string parameterNameOfField(const std::string& field)
{
  return isConfigurationPath(field) ? parameterName(field) : field;
}

/// "table.cloth.friction" → {"table", "cloth", "friction"}: the steps a reader descends by.
std::vector<std::string> pathSteps(const std::string& path);

/// A key that no field of the configuration has, at `field` in a file or request, refused: under a law
/// ("table.cushion.law.yield_speed") it is a parameter the chosen law lacks; elsewhere it is not `what`.
Error unknownField(const std::string& field, const std::string& what);

/// "table/cloth/friction" → "table.cloth.friction".
inline std::string configurationPath(std::string parameter_name)
{
  std::replace(parameter_name.begin(), parameter_name.end(), '/', '.');
  return parameter_name;
}

}  // namespace billiard_shot_planner
