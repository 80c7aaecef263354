#include "billiard_shot_planner/io/json_problems.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
using nlohmann::json;
using Solver = Expected<json> (*)(const json&, const SolverOptions&);

const std::pair<const char*, Solver> PROBLEMS[] = {
    {"ball_ball_table", json_io::solveBallBallTable},
    {"chain", json_io::solveChain},
    {"ball_ball", json_io::solveBallBall},
    {"cue_strike", json_io::solveCueStrike},
    {"ball_table", json_io::solveBallTable},
    {"ball_motion", json_io::solveBallMotion},
    {"shot", json_io::solveShot},
    {"table_shot", json_io::solveTableShot},
    {"plan_shot", json_io::solvePlanShot},
    {"calibrate", json_io::solveCalibrate},
};

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
  for (const auto& [name, solver] : PROBLEMS)
    names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}
}  // namespace

Expected<json> solveJsonProblem(const json& request)
{
  if (!request.is_object())
    return invalidArgument("", "the input must be a JSON object");
  if (!request.contains("problem") || !request.at("problem").is_string())
    return invalidArgument("problem", "is required, one of: " + knownProblems());
  auto options = json_io::solverOptions(request);
  if (!options)
    return options.error();
  const std::string problem = request.at("problem").get<std::string>();
  try
  {
    for (const auto& [name, solver] : PROBLEMS)
      if (problem == name)
        return finiteAnswer(solver(request, options.value()));
  }
  catch (const json::exception& e)
  {
    return invalidArgument("", std::string("malformed input: ") + e.what());
  }
  return invalidArgument("problem", "unknown problem \"" + problem + "\" (known: " + knownProblems() + ")");
}

}  // namespace billiard_shot_planner
