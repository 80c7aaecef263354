#include "billiard_shot_planner/io/json_problems.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "json_configuration_reader.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
using nlohmann::json;
using Solver = Expected<json> (*)(const json&, const SolverOptions&);

/// Arrays and objects nested deeper than any problem's fields (a calibration's track points sit at depth 6).
constexpr std::size_t MAX_REQUEST_DEPTH = 32;

using json_io::ConfigurationPart;

/// A problem: its solver, the top-level fields it reads besides "problem" and "solver" (docs/cli.md, Problems) and
/// the parts of the configuration it reads, whose fields it takes in the request's layout.
struct Problem
{
  const char* name;
  Solver solve;
  std::vector<std::string> fields;
  std::vector<ConfigurationPart> configuration;
};

const std::vector<Problem>& problems()
{
  using Part = ConfigurationPart;
  static const std::vector<Problem> known{
      {"ball_ball_table", json_io::solveBallBallTable, {"e1", "e2", "m1", "m2", "stiffness_ratio", "v0"}, {}},
      {"chain", json_io::solveChain, {"masses", "restitution", "stiffness", "velocities", "wall"}, {}},
      {"ball_ball",
       json_io::solveBallBall,
       {"ball_ball", "ball_mass", "ball_radius", "balls", "cloth", "stiffness_ratio", "table_file",
        "touching_tolerance"},
       {}},
      {"cue_strike",
       json_io::solveCueStrike,
       {"ball_centre", "cue", "cue_axis_point", "cue_direction", "cue_speed", "hit_normal"},
       {Part::Strike}},
      {"ball_table",
       json_io::solveBallTable,
       {"angular_velocity", "mass", "radius", "table", "table_file", "velocity"},
       {}},
      {"ball_motion", json_io::solveBallMotion, {"omega", "position", "sample_spacing", "v"}, {Part::Motion}},
      {"shot",
       json_io::solveShot,
       {"ball_centre", "ball_position", "cue", "cue_axis_point", "cue_direction", "cue_speed", "hit_normal",
        "sample_spacing"},
       {Part::Strike, Part::Motion}},
      {"table_shot",
       json_io::solveTableShot,
       {"ball_centre", "balls", "cue", "cue_axis_point", "cue_ball", "cue_direction", "cue_speed", "hit_normal",
        "sample_spacing", "samples"},
       {Part::Strike, Part::Motion, Part::BallContact}},
      {"plan_shot",
       json_io::solvePlanShot,
       {"balls", "budget_ms", "cue_ball", "cue_region", "limits", "noise", "pocket", "rollouts", "rules", "seed",
        "target", "threads"},
       {Part::Strike, Part::Motion, Part::BallContact}},
      {"calibrate",
       json_io::solveCalibrate,
       {"budget_ms", "fit", "position_noise", "robust_loss_sigmas", "shots", "starts", "threads"},
       {Part::Strike, Part::Motion, Part::BallContact}},
  };
  return known;
}

/// A problem that strikes without moving the ball on (cue_strike) reads only the cloth of its "table".
Status onlyTheClothOfAStrike(const Problem& problem, const std::string& key, const json& value)
{
  const auto reads = [&problem](ConfigurationPart part) {
    return std::find(problem.configuration.begin(), problem.configuration.end(), part) != problem.configuration.end();
  };
  if (key != "table" || !value.is_object() || !reads(ConfigurationPart::Strike) || reads(ConfigurationPart::Motion))
    return {};
  for (const auto& item : value.items())
    if (item.key() != "cloth")
      return invalidArgument("table." + item.key(), "is not a field of the problem \"" + std::string(problem.name) +
                                                        "\": a strike reads only the table's cloth");
  return {};
}

/// A top-level field the problem does not read is refused: a misspelt or misplaced constant would otherwise be
/// ignored and the answer computed without it.
Status onlyFieldsOf(const Problem& problem, const json& request)
{
  const std::vector<std::string> configuration = json_io::requestFieldsOf(problem.configuration);
  for (const auto& item : request.items())
  {
    const std::string& key = item.key();
    const auto listed = [&key](const std::vector<std::string>& names)
    { return std::find(names.begin(), names.end(), key) != names.end(); };
    if (key == "problem" || key == "solver" || listed(problem.fields) || listed(configuration))
    {
      if (Status status = onlyTheClothOfAStrike(problem, key, item.value()); !status)
        return status;
      continue;
    }
    return invalidArgument(
        key, "is not a field of the problem \"" + std::string(problem.name) + "\" (docs/cli.md lists its fields)");
  }
  return {};
}

/// How deep arrays and objects nest in `value`, counted without recursion: a request nested a hundred thousand
/// levels deep would overflow the stack of any recursive reader (copying a json value is one).
std::size_t nestingDepth(const json& value)
{
  std::size_t deepest = 0;
  std::vector<std::pair<const json*, std::size_t>> open{{&value, 1}};
  while (!open.empty())
  {
    const auto [node, depth] = open.back();
    open.pop_back();
    if (!node->is_structured())
      continue;
    deepest = std::max(deepest, depth);
    if (deepest > MAX_REQUEST_DEPTH)
      return deepest;
    for (const json& item : *node)
      open.emplace_back(&item, depth + 1);
  }
  return deepest;
}

/// `path` extended by one step: a key of an object, or an index of an array.
std::string pathTo(const std::string& path, const std::string& key)
{
  std::string extended = path;
  if (!extended.empty())
    extended += '.';
  extended += key;
  return extended;
}

std::string pathTo(const std::string& path, std::size_t index)
{
  std::string extended = path;
  extended += '[';
  extended += std::to_string(index);
  extended += ']';
  return extended;
}

/// The path of the first number in `value` that is NaN or infinite (JSON would write it as null), if any.
std::optional<std::string> nonFinitePath(const json& value, const std::string& path)
{
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    return path.empty() ? "answer" : path;
  if (value.is_object())
    for (const auto& [key, item] : value.items())
      if (auto found = nonFinitePath(item, pathTo(path, key)))
        return found;
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      if (auto found = nonFinitePath(value[i], pathTo(path, i)))
        return found;
  return std::nullopt;
}

/// An answer never carries NaN or infinity: one that would is a numerical failure, named where it happened.
Expected<json> finiteAnswer(Expected<json> answer)
{
  if (!answer)
    return answer;
  if (auto path = nonFinitePath(answer.value(), ""))
    return Error{ErrorKind::NumericalFailure, *path, "the answer is not finite here (a numerical failure)"};
  return answer;
}

std::string knownProblems()
{
  std::string names;
  for (const Problem& problem : problems())
    names += (names.empty() ? "" : ", ") + std::string(problem.name);
  return names;
}
}  // namespace

Expected<json> solveJsonProblem(const json& request)
{
  if (!request.is_object())
    return invalidArgument("", "the input must be a JSON object");
  if (nestingDepth(request) > MAX_REQUEST_DEPTH)
    return invalidArgument("", "nests deeper than " + std::to_string(MAX_REQUEST_DEPTH) +
                                   " levels: no problem has such fields (docs/cli.md)");
  if (!request.contains("problem") || !request.at("problem").is_string())
    return invalidArgument("problem", "is required, one of: " + knownProblems());
  auto options = json_io::solverOptions(request);
  if (!options)
    return options.error();
  const std::string problem = request.at("problem").get<std::string>();
  try
  {
    for (const Problem& known : problems())
      if (problem == known.name)
      {
        if (Status status = onlyFieldsOf(known, request); !status)
          return status.error();
        return finiteAnswer(known.solve(request, options.value()));
      }
  }
  catch (const json::exception& e)
  {
    return invalidArgument("", std::string("malformed input: ") + e.what());
  }
  return invalidArgument("problem", "unknown problem \"" + problem + "\" (known: " + knownProblems() + ")");
}

}  // namespace billiard_shot_planner
