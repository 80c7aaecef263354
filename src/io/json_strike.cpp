#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
std::vector<double> toVector(const Eigen::Vector3d& v)
{
  return {v.x(), v.y(), v.z()};
}

Expected<SurfaceContact> surfaceContact(const json& request, const std::string& key)
{
  auto fields = object(request, key, true);
  if (!fields)
    return fields.error();
  SurfaceContact surface;
  for (auto [name, target] : {std::pair{"restitution", &surface.restitution}, std::pair{"friction", &surface.friction},
                              std::pair{"eta2", &surface.eta2}})
  {
    auto value = number(fields.value(), name);
    if (!value)
      return nested(key, value.error());
    *target = value.value();
  }
  return surface;
}

/// The hit normal as given, or from the cue axis ("cue_axis_point") and the ball centre ("ball_centre").
Expected<Eigen::Vector3d> hitNormalField(const json& request, const CueStrike& strike)
{
  if (request.contains("hit_normal") || !request.contains("cue_axis_point"))
    return vector3(request, "hit_normal");
  auto point = vector3(request, "cue_axis_point");
  if (!point)
    return point.error();
  auto centre = vector3(request, "ball_centre", Eigen::Vector3d(0.0, 0.0, strike.ball_radius));
  if (!centre)
    return centre.error();
  return hitNormal(point.value(), strike.cue_direction, centre.value(), strike.ball_radius);
}

}  // namespace

Expected<CueStrike> cueStrikeFromJson(const json& request)
{
  CueStrike strike;
  if (Status status = readNumbers(request,
                                  {{"cue_mass", &strike.cue_mass},
                                   {"cue_speed", &strike.cue_speed},
                                   {"ball_mass", &strike.ball_mass},
                                   {"ball_radius", &strike.ball_radius},
                                   {"stiffness_ratio", &strike.stiffness_ratio}},
                                  "", Presence::Required);
      !status)
    return status.error();
  auto direction = vector3(request, "cue_direction");
  if (!direction)
    return direction.error();
  strike.cue_direction = direction.value();
  for (auto [name, target] :
       {std::pair{"cue_contact", &strike.cue_contact}, std::pair{"table_contact", &strike.table_contact}})
  {
    auto surface = surfaceContact(request, name);
    if (!surface)
      return surface.error();
    *target = surface.value();
  }
  auto normal = hitNormalField(request, strike);
  if (!normal)
    return normal.error();
  strike.hit_normal = normal.value();
  return strike;
}

json cueStrikeJson(const CueStrikeResult& r)
{
  json out = commonResultJson(r.impact, {"cue-ball", "ball-table"});
  out["v"] = toVector(r.velocity);
  out["omega"] = toVector(r.angular_velocity);
  out["cue_velocity"] = r.cue_velocity;
  out["states"] = r.states;
  out["impulse_cue"] = toVector(r.impulse_cue);
  out["impulse_table"] = toVector(r.impulse_table);
  out["hit_normal"] = toVector(r.hit_normal);
  out["miscue"] = r.miscue;
  return out;
}

Expected<StrikeAnswer> solveStrikeFromJson(const json& request, const SolverOptions& options)
{
  auto strike = cueStrikeFromJson(request);
  if (!strike)
    return strike.error();
  auto result = solve(strike.value(), options);
  if (!result)
    return result.error();
  return StrikeAnswer{std::move(strike).value(), std::move(result).value()};
}

Expected<json> solveCueStrike(const json& request, const SolverOptions& options)
{
  auto answer = solveStrikeFromJson(request, options);
  if (!answer)
    return answer.error();
  return cueStrikeJson(answer.value().result);
}

Expected<json> solveBallTable(const json& request, const SolverOptions& options)
{
  BallTableImpact impact;
  if (Status status =
          readNumbers(request, {{"mass", &impact.mass}, {"radius", &impact.radius}}, "", Presence::Required);
      !status)
    return status.error();
  auto velocity = vector3(request, "velocity");
  if (!velocity)
    return velocity.error();
  impact.velocity = velocity.value();
  auto spin = vector3(request, "angular_velocity", Eigen::Vector3d::Zero());
  if (!spin)
    return spin.error();
  impact.angular_velocity = spin.value();
  auto table = surfaceContact(request, "table");
  if (!table)
    return table.error();
  impact.table = table.value();
  auto result = solve(impact, options);
  if (!result)
    return result.error();
  const BallTableImpactResult& r = result.value();
  json out = commonResultJson(r.impact, {"ball-table"});
  out["v"] = toVector(r.velocity);
  out["omega"] = toVector(r.angular_velocity);
  out["impulse"] = toVector(r.impulse);
  return out;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
