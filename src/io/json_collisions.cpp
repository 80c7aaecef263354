#include <string>
#include <tuple>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
Expected<json> solveBallBallTable(const json& request, const SolverOptions& options)
{
  BallBallTable c;
  // m1 and v0 default to the paper's normalisation (m1 = 1, v0 = −1); the rest are required.
  if (Status status = firstError(
          {readNumbers(request, {{"m2", &c.m2}, {"stiffness_ratio", &c.stiffness_ratio}, {"e1", &c.e1}, {"e2", &c.e2}},
                       "", Presence::Required),
           readNumbers(request, {{"m1", &c.m1}, {"v0", &c.v0}})});
      !status)
    return status.error();
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
}  // namespace json_io
}  // namespace billiard_shot_planner
