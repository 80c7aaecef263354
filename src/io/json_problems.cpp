#include "billiard_shot_planner/io/json_problems.hpp"

#include <string>

#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
using nlohmann::json;
using Solver = Expected<json> (*)(const json&, const SolverOptions&);

const std::pair<const char*, Solver> PROBLEMS[] = {
    {"ball_ball_table", json_io::solveBallBallTable}, {"chain", json_io::solveChain},
    {"cue_strike", json_io::solveCueStrike},          {"ball_table", json_io::solveBallTable},
    {"ball_motion", json_io::solveBallMotion},        {"shot", json_io::solveShot},
};

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
        return solver(request, options.value());
  }
  catch (const json::exception& e)
  {
    return invalidArgument("", std::string("malformed input: ") + e.what());
  }
  return invalidArgument("problem", "unknown problem \"" + problem + "\" (known: " + knownProblems() + ")");
}

}  // namespace billiard_shot_planner
