#include "billiard_shot_planner/io/json_problems.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"

namespace billiard_shot_planner
{
namespace
{
using nlohmann::json;

Expected<double> number(const json& object, const char* key, std::optional<double> fallback = std::nullopt)
{
  if (!object.contains(key))
  {
    if (fallback)
      return *fallback;
    return invalidArgument(key, "is required");
  }
  const json& value = object.at(key);
  if (!value.is_number())
    return invalidArgument(key, "must be a number");
  return value.get<double>();
}

Expected<std::vector<double>> numbers(const json& object, const char* key)
{
  if (!object.contains(key))
    return invalidArgument(key, "is required");
  const json& value = object.at(key);
  if (!value.is_array())
    return invalidArgument(key, "must be an array of numbers");
  std::vector<double> out;
  for (const json& item : value)
  {
    if (!item.is_number())
      return invalidArgument(key, "must be an array of numbers");
    out.push_back(item.get<double>());
  }
  return out;
}

Expected<SolverOptions> solverOptions(const json& request)
{
  SolverOptions options;
  if (!request.contains("solver"))
    return options;
  const json& solver = request.at("solver");
  if (!solver.is_object())
    return invalidArgument("solver", "must be an object");
  for (auto [key, target] : {std::pair{"relative_tolerance", &options.relative_tolerance},
                             std::pair{"absolute_tolerance", &options.absolute_tolerance}})
  {
    auto value = number(solver, key, *target);
    if (!value)
      return invalidArgument(std::string("solver.") + key, value.error().message);
    if (!(value.value() > 0.0 && value.value() < 1e-2))
      return invalidArgument(std::string("solver.") + key, "must be in (0, 0.01)");
    *target = value.value();
  }
  auto max_events = number(solver, "max_events", static_cast<double>(options.max_events));
  if (!max_events || !(max_events.value() >= 1.0 && max_events.value() <= 1e9))
    return invalidArgument("solver.max_events", "must be a number in [1, 1e9]");
  options.max_events = static_cast<std::size_t>(max_events.value());
  if (solver.contains("record_samples"))
  {
    if (!solver.at("record_samples").is_boolean())
      return invalidArgument("solver.record_samples", "must be true or false");
    options.record_samples = solver.at("record_samples").get<bool>();
  }
  return options;
}

std::vector<double> toVector(const Eigen::VectorXd& v)
{
  return std::vector<double>(v.data(), v.data() + v.size());
}

json snapshotJson(const ImpactSnapshot& snap)
{
  return json{{"time", snap.time},
              {"impulses", toVector(snap.normal_impulses)},
              {"velocities", toVector(snap.velocity)},
              {"strain_energies", toVector(snap.strain_energies)},
              {"total_energy", snap.total_energy()}};
}

/// The parts of a result that every problem reports the same way.
json commonResultJson(const ImpactResult& result)
{
  json events = json::array();
  for (const ContactEvent& event : result.events)
  {
    json e = snapshotJson(event.at);
    e["type"] = toString(event.type);
    e["contact"] = event.contact;
    events.push_back(e);
  }
  json out{{"ends_of_compression", result.ends_of_compression},
           {"converged", result.converged},
           {"events", events},
           {"energy",
            {{"initial", result.initial_kinetic_energy},
             {"final", result.final_kinetic_energy},
             {"lost", result.initial_kinetic_energy - result.final_kinetic_energy}}}};
  if (!result.samples.empty())
  {
    json samples = json::array();
    for (const ImpactSnapshot& snap : result.samples)
      samples.push_back(snapshotJson(snap));
    out["samples"] = samples;
  }
  return out;
}

Expected<json> solveBallBallTable(const json& request, const SolverOptions& options)
{
  BallBallTable c;
  // m1 and v0 default to the paper's normalisation (m1 = 1, v0 = −1); the rest are required.
  const std::optional<double> required;
  for (auto [key, target, fallback] :
       {std::tuple{"m1", &c.m1, std::optional<double>(c.m1)}, std::tuple{"m2", &c.m2, required},
        std::tuple{"stiffness_ratio", &c.stiffness_ratio, required}, std::tuple{"e1", &c.e1, required},
        std::tuple{"e2", &c.e2, required}, std::tuple{"v0", &c.v0, std::optional<double>(c.v0)}})
  {
    auto value = number(request, key, fallback);
    if (!value)
      return value.error();
    *target = value.value();
  }
  auto result = solve(c, options);
  if (!result)
    return result.error();
  const ImpactResult& r = result.value();
  json out = commonResultJson(r);
  out["v1"] = r.velocity(0);
  out["v2"] = r.velocity(1);
  out["I1"] = r.impulses[0].normal;
  out["I2"] = r.impulses[1].normal;
  out["states"] = ballBallTableStates(r);
  json starts = json::array();
  for (const ImpactState& state : r.states)
  {
    json s = snapshotJson(state.start);
    s["state"] = ballBallTableStateName(state.active);
    starts.push_back(s);
  }
  out["state_starts"] = starts;
  return out;
}

Expected<json> solveChain(const json& request, const SolverOptions& options)
{
  BallChain chain;
  for (auto [key, target] : {std::pair{"masses", &chain.masses}, std::pair{"velocities", &chain.velocities},
                             std::pair{"stiffness", &chain.stiffness}, std::pair{"restitution", &chain.restitution}})
  {
    auto value = numbers(request, key);
    if (!value)
      return value.error();
    *target = value.value();
  }
  if (request.contains("wall"))
  {
    if (!request.at("wall").is_boolean())
      return invalidArgument("wall", "must be true or false");
    chain.wall = request.at("wall").get<bool>();
  }
  auto result = solve(chain, options);
  if (!result)
    return result.error();
  const ImpactResult& r = result.value();
  json out = commonResultJson(r);
  out["velocities"] = toVector(r.velocity);
  std::vector<double> impulses;
  for (const ContactImpulse& impulse : r.impulses)
    impulses.push_back(impulse.normal);
  out["impulses"] = impulses;
  json states = json::array();
  for (const ImpactState& state : r.states)
    states.push_back(state.active);
  out["states"] = states;
  return out;
}
}  // namespace

Expected<json> solveJsonProblem(const json& request)
{
  if (!request.is_object())
    return invalidArgument("", "the input must be a JSON object");
  if (!request.contains("problem") || !request.at("problem").is_string())
    return invalidArgument("problem", "is required: \"ball_ball_table\" or \"chain\"");
  auto options = solverOptions(request);
  if (!options)
    return options.error();
  const std::string problem = request.at("problem").get<std::string>();
  try
  {
    if (problem == "ball_ball_table")
      return solveBallBallTable(request, options.value());
    if (problem == "chain")
      return solveChain(request, options.value());
  }
  catch (const json::exception& e)
  {
    return invalidArgument("", std::string("malformed input: ") + e.what());
  }
  return invalidArgument("problem", "unknown problem \"" + problem + "\" (known: ball_ball_table, chain)");
}

}  // namespace billiard_shot_planner
