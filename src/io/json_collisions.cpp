#include <algorithm>
#include <cstring>
#include <string>
#include <tuple>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"
#include "json_configuration_reader.hpp"
#include "json_fields.hpp"
#include "json_motion.hpp"

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
namespace
{
/// "ball_ball" or "cloth": {"restitution", "friction", "eta2", "law"}, each optional over `surface`.
Status readSurface(const json& request, const std::string& key, SurfaceContact& surface)
{
  auto fields = object(request, key, false);
  if (!fields)
    return fields.error();
  // The ball–ball object also holds its friction model and the cloth's stiffness relative to it.
  if (key == "ball_ball")
    return readSurfaceContact(fields.value(), key, surface, Presence::Optional,
                              {"friction_model", "cloth_stiffness_ratio"});
  return readSurfaceContact(fields.value(), key, surface);
}

/// The ball–ball friction: a constant "friction", or "friction_model": "alciatore" (or "constant" with "friction").
Status readBallBallFriction(const json& request, BallCollision& collision)
{
  const json fields = request.value("ball_ball", json::object());
  if (Status status = checkFrictionModel(fields); !status)
    return status;
  if (fields.is_object() && fields.contains("friction"))
    collision.friction_model = BallBallFriction::Constant;
  else if (fields.is_object() && fields.contains("friction_model"))
    collision.friction_model = BallBallFriction::Alciatore;
  return {};
}

Expected<CollidingBall> collidingBall(const json& fields, const std::string& prefix)
{
  if (!fields.is_object())
    return invalidArgument(prefix, "must be an object {\"position\": [x, y], \"v\": [x, y, z], \"omega\": [x, y, z]}");
  auto state = ballOnCloth(fields, prefix, 0.0);
  if (!state)
    return state.error();
  return CollidingBall{state.value().position.head<2>(), state.value().velocity, state.value().angular_velocity};
}

Status readBalls(const json& request, BallCollision& collision)
{
  if (!request.contains("balls") || !request.at("balls").is_array())
    return invalidArgument("balls", "is required: an array of {\"position\", \"v\", \"omega\"}");
  const json& balls = request.at("balls");
  for (std::size_t i = 0; i < balls.size(); ++i)
  {
    auto ball = collidingBall(balls[i], "balls[" + std::to_string(i) + "]");
    if (!ball)
      return ball.error();
    collision.balls.push_back(ball.value());
  }
  return {};
}

/// The constants a collision starts from: a table file's ball–ball contact and cloth when the request names one
/// (its balls are for library callers: the request gives its own), else the defaults.
Expected<BallCollision> collisionBase(const json& request)
{
  BallCollision collision;
  if (!request.contains("table_file"))
    return collision;
  auto file = tableFile(request);
  if (!file)
    return file.error();
  const BallContactSettings& contact = file.value().ball_contact;
  collision.ball_ball = contact.ball_ball;
  collision.friction_model = contact.friction_model;
  collision.stiffness_ratio = contact.stiffness_ratio;
  collision.cloth = file.value().table.cloth;
  return collision;
}

Expected<BallCollision> ballCollisionFromJson(const json& request)
{
  auto base = collisionBase(request);
  if (!base)
    return base.error();
  BallCollision collision = base.value();
  // The cloth's stiffness relative to the balls', as a table's ball_ball gives it or at the top level: one of them.
  if (const json fields = request.value("ball_ball", json::object());
      fields.is_object() && fields.contains("cloth_stiffness_ratio"))
  {
    if (request.contains("stiffness_ratio"))
      return invalidArgument("stiffness_ratio", "give it once: here or as ball_ball.cloth_stiffness_ratio");
    if (Status status =
            firstError({readNumbers(fields, {{"cloth_stiffness_ratio", &collision.stiffness_ratio}}, "ball_ball"),
                        requireStiffnessRatio(collision.stiffness_ratio, "ball_ball.cloth_stiffness_ratio")});
        !status)
      return status.error();
  }
  if (Status status =
          firstError({readBalls(request, collision), readSurface(request, "ball_ball", collision.ball_ball),
                      readSurface(request, "cloth", collision.cloth), readBallBallFriction(request, collision),
                      readNumbers(request, {{"ball_mass", &collision.ball_mass},
                                            {"ball_radius", &collision.ball_radius},
                                            {"stiffness_ratio", &collision.stiffness_ratio},
                                            {"touching_tolerance", &collision.touching_tolerance}})});
      !status)
    return status.error();
  return collision;
}

}  // namespace

Expected<BallContactSettings> ballContactFromJson(const json& request)
{
  auto configuration = requestConfiguration(request);
  if (!configuration)
    return configuration.error();
  const BallContactSettings& contact = configuration.value().ball_contact;
  if (Status status = firstError({validate(contact.ball_ball, "ball_ball"),
                                  requireStiffnessRatio(contact.stiffness_ratio, "ball_ball.cloth_stiffness_ratio")});
      !status)
    return status.error();
  return contact;
}

namespace
{
/// The scenario names a ball's fields as BallCollision does ("balls[2].velocity"); the request calls them v, omega.
Error inRequestTerms(Error error)
{
  for (auto [field, key] : {std::pair{".velocity", ".v"}, std::pair{".angular_velocity", ".omega"}})
  {
    const std::size_t at = error.field.rfind(field);
    if (error.field.rfind("balls[", 0) == 0 && at != std::string::npos && at + std::strlen(field) == error.field.size())
      error.field.replace(at, std::strlen(field), key);
  }
  return error;
}

json contactJson(const BallCollisionResult& r, std::size_t k)
{
  const ContactImpulse& impulse = r.impact.impulses[k];
  json contact{
      {"name", r.contact_names[k]},
      {"impulse", {{"normal", impulse.normal}, {"tangential", {impulse.tangential.x(), impulse.tangential.y()}}}}};
  if (k < r.pairs.size())
  {
    contact["balls"] = {r.pairs[k].b, r.pairs[k].a};
    contact["friction"] = r.pairs[k].friction;
  }
  else
  {
    const auto ball = std::find(r.cloth_contacts.begin(), r.cloth_contacts.end(), k);
    contact["ball"] = static_cast<std::size_t>(ball - r.cloth_contacts.begin());
  }
  return contact;
}
}  // namespace

Expected<json> solveBallBall(const json& request, const SolverOptions& options)
{
  auto collision = ballCollisionFromJson(request);
  if (!collision)
    return collision.error();
  auto result = solve(collision.value(), options);
  if (!result)
    return inRequestTerms(result.error());
  const BallCollisionResult& r = result.value();
  json out = commonResultJson(r.impact, r.contact_names);
  json balls = json::array();
  for (const CollidedBall& ball : r.balls)
    balls.push_back({{"v", {ball.velocity.x(), ball.velocity.y(), ball.velocity.z()}},
                     {"omega", {ball.angular_velocity.x(), ball.angular_velocity.y(), ball.angular_velocity.z()}}});
  out["balls"] = balls;
  json contacts = json::array();
  for (std::size_t k = 0; k < r.impact.impulses.size(); ++k)
    contacts.push_back(contactJson(r, k));
  out["contacts"] = contacts;
  json states = json::array();
  for (const ImpactState& state : r.impact.states)
    states.push_back(state.active);
  out["states"] = states;
  return out;
}
}  // namespace json_io
}  // namespace billiard_shot_planner
