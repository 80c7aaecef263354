#include <cmath>
#include <optional>

#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/cue_stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "json_configuration_reader.hpp"
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

/// The contact `key` of the request: every constant required, or, given `defaults`, each constant it omits (or the
/// whole contact) theirs.
Expected<SurfaceContact> surfaceContact(const json& request, const std::string& key,
                                        const std::optional<SurfaceContact>& defaults = std::nullopt)
{
  auto fields = object(request, key, !defaults);
  if (!fields)
    return fields.error();
  SurfaceContact surface = defaults.value_or(SurfaceContact{});
  if (Status status =
          readSurfaceContact(fields.value(), key, surface, defaults ? Presence::Optional : Presence::Required);
      !status)
    return status.error();
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

/// The cue as a stroke, "cue": {"phi_deg", "theta_deg", "speed", "a", "b"}, in place of cue_direction, cue_speed
/// and the hit point.
Status readStroke(const json& request, CueStrike& strike)
{
  for (const char* key : {"cue_direction", "cue_speed", "hit_normal", "cue_axis_point", "ball_centre"})
    if (request.contains(key))
      return invalidArgument(key,
                             "give the cue either as \"cue\" or by cue_direction, cue_speed and the hit point, "
                             "not both");
  auto fields = object(request, "cue", true);
  if (!fields)
    return fields.error();
  auto given = strokeFromJson(fields.value(), "cue", strike.ball_radius);
  if (!given)
    return given.error();
  strike.cue_speed = given.value().speed;
  const CueStroke stroke{given.value().phi, given.value().theta, given.value().a, given.value().b};
  auto geometry = strokeGeometry(stroke);
  if (!geometry)
  {
    Error error = nested("cue", geometry.error());
    if (error.field == "cue.phi" || error.field == "cue.theta")
      error.field += "_deg";
    return error;
  }
  strike.cue_direction = geometry.value().cue_direction;
  strike.hit_normal = geometry.value().hit_normal;
  return {};
}

/// The cue by its direction, its speed and the hit point (as a normal, or where the cue's axis meets the ball).
Status readCueAndHitPoint(const json& request, CueStrike& strike)
{
  if (Status status = readNumbers(request, {{"cue_speed", &strike.cue_speed}}, "", Presence::Required); !status)
    return status;
  auto direction = vector3(request, "cue_direction");
  if (!direction)
    return direction.error();
  strike.cue_direction = direction.value();
  auto normal = hitNormalField(request, strike);
  if (!normal)
    return normal.error();
  strike.hit_normal = normal.value();
  return {};
}
}  // namespace

Expected<CueStrike> strikePhysicsFromJson(const json& request)
{
  auto configuration = requestConfiguration(request);  // over the node's defaults: config/default.yaml
  if (!configuration)
    return configuration.error();
  CueStrike strike = strikePhysics(configuration.value());
  auto cloth = strikeCloth(request, configuration.value());
  if (!cloth)
    return cloth.error();
  strike.table_contact = cloth.value();
  return strike;
}

Expected<CueStrike> cueStrikeFromJson(const json& request)
{
  auto strike = strikePhysicsFromJson(request);
  if (!strike)
    return strike;
  Status cue =
      request.contains("cue") ? readStroke(request, strike.value()) : readCueAndHitPoint(request, strike.value());
  if (!cue)
    return cue.error();
  return strike;
}

namespace
{
std::vector<std::string> contactNames(const CueStrikeResult& r)
{
  std::vector<std::string> names;
  for (const StrikeContact& contact : r.contacts)
    names.push_back(contact.name);
  return names;
}

/// A ball of the table by its index, or the index itself where the caller gives no ids.
json ballLabel(std::size_t ball, const std::vector<std::string>& ids)
{
  return ball < ids.size() ? json(ids[ball]) : json(ball);
}
}  // namespace

json cueStrikeJson(const CueStrikeResult& r, const std::vector<std::string>& ids)
{
  json out = commonResultJson(r.impact, contactNames(r));
  out["v"] = toVector(r.velocity);
  out["omega"] = toVector(r.angular_velocity);
  out["cue_velocity"] = r.cue_velocity;
  out["tip_velocity"] = toVector(r.tip_velocity);
  out["states"] = r.states;
  out["impulse_cue"] = toVector(r.impulse_cue);
  out["impulse_table"] = toVector(r.impulse_table);
  out["hit_normal"] = toVector(r.hit_normal);
  out["cue_direction"] = toVector(r.cue_direction);
  out["miscue"] = r.miscue;
  out["leaves_cloth"] = r.leaves_cloth;
  json contacts = json::array(), moved = json::array(), touching = json::array();
  for (const StrikeContact& contact : r.contacts)
    contacts.push_back({{"name", contact.name}, {"impulse", toVector(contact.impulse)}});
  for (const StruckBall& ball : r.other_balls)
    moved.push_back({{"id", ballLabel(ball.ball, ids)},
                     {"v", toVector(ball.velocity)},
                     {"omega", toVector(ball.angular_velocity)}});
  for (const TouchingBalls& pair : r.touching_balls)
    touching.push_back({ballLabel(pair.first, ids), ballLabel(pair.second, ids)});
  out["contacts"] = contacts;
  out["other_balls"] = moved;
  out["touching"] = touching;
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
  // A table file gives the cloth's constants, which the request's "table" then overrides one by one.
  std::optional<SurfaceContact> cloth;
  if (request.contains("table_file"))
  {
    auto file = tableFile(request);
    if (!file)
      return file.error();
    cloth = file.value().table.cloth;
  }
  auto table = surfaceContact(request, "table", cloth);
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
