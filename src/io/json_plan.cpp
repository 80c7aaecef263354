// The plan_shot problem: which stroke pots a ball, and how likely it is under the robot's noise.
#include <cmath>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "json_configuration.hpp"
#include "json_configuration_reader.hpp"
#include "json_fields.hpp"
#include "json_table.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
constexpr double DEG = M_PI / 180.0;

/// object[key] as [low, high].
Status readRange(const json& object, const std::string& key, const std::string& field, double& low, double& high,
                 double scale)
{
  if (!object.contains(key))
    return {};
  auto values = numbers(object, key);
  if (!values || values.value().size() != 2)
    return invalidArgument(field, "must be [min, max]");
  low = values.value()[0] * scale;
  high = values.value()[1] * scale;
  return {};
}

Status readLimits(const json& request, RobotLimits& limits)
{
  auto fields = object(request, "limits", false);
  if (!fields)
    return fields.error();
  const json& l = fields.value();
  if (Status status = readRange(l, "theta_deg", "limits.theta_deg", limits.min_theta, limits.max_theta, DEG); !status)
    return status;
  if (Status status = readRange(l, "speed", "limits.speed", limits.min_speed, limits.max_speed, 1.0); !status)
    return status;
  return readNumbers(l,
                     {{"max_offset", &limits.max_offset},
                      {"cue_length", &limits.cue_length},
                      {"cue_radius", &limits.cue_radius},
                      {"rail_height", &limits.rail_height}},
                     "limits");
}

/// "noise": {"phi_deg", "theta_deg", "speed", "a", "b"}: σ in degrees, m/s and millimetres (FastFiz's units).
Status readNoise(const json& request, ExecutionNoise& noise)
{
  auto fields = object(request, "noise", false);
  if (!fields)
    return fields.error();
  double phi_deg = noise.phi / DEG, theta_deg = noise.theta / DEG, a_mm = noise.a * 1e3, b_mm = noise.b * 1e3;
  if (Status status = readNumbers(
          fields.value(),
          {{"phi_deg", &phi_deg}, {"theta_deg", &theta_deg}, {"speed", &noise.speed}, {"a", &a_mm}, {"b", &b_mm}},
          "noise");
      !status)
    return status;
  noise = {phi_deg * DEG, theta_deg * DEG, noise.speed, a_mm * 1e-3, b_mm * 1e-3};
  return {};
}

Status readRegionAndRules(const json& request, PlanRequest& plan)
{
  if (request.contains("cue_region"))
  {
    auto fields = object(request, "cue_region", true);
    if (!fields)
      return fields.error();
    auto centre = vector2(fields.value(), "centre");
    if (!centre)
      return nested("cue_region", centre.error());
    CueRegion region{centre.value(), 0.0};
    if (Status status = readNumbers(fields.value(), {{"radius", &region.radius}}, "cue_region", Presence::Required);
        !status)
      return status;
    plan.cue_region = region;
  }
  auto rules = object(request, "rules", false);
  if (!rules)
    return rules.error();
  for (auto [key, flag] :
       {std::pair{"target_first", &plan.rules.target_first}, std::pair{"only_target", &plan.rules.only_target}})
    if (rules.value().contains(key))
    {
      if (!rules.value().at(key).is_boolean())
        return invalidArgument(std::string("rules.") + key, "must be true or false");
      *flag = rules.value().at(key).get<bool>();
    }
  return {};
}

/// An integer field: a number with no fractional part within [low, high].
Status readInteger(const json& request, const std::string& key, double low, double high, int& value)
{
  if (!request.contains(key))
    return {};
  auto read = number(request, key);
  if (!read)
    return read.error();
  if (read.value() != std::floor(read.value()) || read.value() < low || read.value() > high)
    return invalidArgument(key, "must be an integer in [" + std::to_string(static_cast<long long>(low)) + ", " +
                                    std::to_string(static_cast<long long>(high)) + "]");
  value = static_cast<int>(read.value());
  return {};
}

Status readSearch(const json& request, PlanRequest& plan)
{
  if (request.contains("target"))
  {
    if (!request.at("target").is_string())
      return invalidArgument("target", "must be the id of a ball");
    plan.target = request.at("target").get<std::string>();
  }
  if (request.contains("pocket"))
  {
    if (!request.at("pocket").is_string())
      return invalidArgument("pocket",
                             "must be the id of a pocket (\"top_right\", …; the table's ids: docs/tables.md)");
    plan.pocket = request.at("pocket").get<std::string>();
  }
  double budget_ms = plan.budget * 1e3, seed = plan.seed;
  if (Status status = readNumbers(request, {{"budget_ms", &budget_ms}, {"seed", &seed}}); !status)
    return status;
  if (!(seed >= 0.0 && seed <= 4294967295.0 && seed == std::floor(seed)))
    return invalidArgument("seed", "must be an integer in [0, 2^32 − 1]");
  plan.budget = budget_ms * 1e-3;
  plan.seed = static_cast<unsigned>(seed);
  return firstError(
      {readInteger(request, "rollouts", 1, 1e5, plan.rollouts), readInteger(request, "threads", 0, 256, plan.threads)});
}

Expected<PlanRequest> planRequest(const json& request, double radius)
{
  PlanRequest plan;
  auto balls = tableBalls(request, radius);
  if (!balls)
    return balls.error();
  plan.balls = balls.value();
  auto cue = cueBallIndex(request, plan.balls);
  if (!cue)
    return cue.error();
  plan.cue_ball = plan.balls[cue.value()].id;
  if (Status status = firstError({readLimits(request, plan.limits), readNoise(request, plan.noise),
                                  readRegionAndRules(request, plan), readSearch(request, plan)});
      !status)
    return status.error();
  return plan;
}

/// The planner names its fields in SI units; the request names some in degrees and milliseconds.
Error inRequestTerms(Error error)
{
  for (auto [core, request] : {std::pair{"noise.phi", "noise.phi_deg"}, std::pair{"noise.theta", "noise.theta_deg"},
                               std::pair{"limits.theta", "limits.theta_deg"}, std::pair{"budget", "budget_ms"}})
    if (error.field == core)
      error.field = request;
  return inRequestLayout(error);  // the configuration's motion constants sit at the request's top level
}

json strokeJson(const Stroke& stroke)
{
  return {{"phi_deg", stroke.phi / DEG},
          {"theta_deg", stroke.theta / DEG},
          {"speed", stroke.speed},
          {"a", stroke.a},
          {"b", stroke.b}};
}

json shotJson(const PlannedShot& shot)
{
  return {{"target", shot.target},
          {"pocket", shot.pocket},
          {"bank_cushion", shot.bank_cushion.empty() ? json(nullptr) : json(shot.bank_cushion)},
          {"cue_ball_path", toString(shot.cue_ball_path)},
          {"cue", strokeJson(shot.stroke)},
          {"cue_pose", {{"tip", toVector(shot.cue.tip)}, {"direction", toVector(shot.cue.direction)}}},
          {"margin", shot.margin},
          {"success_probability", shot.success_probability},
          {"confidence_interval", {shot.confidence_low, shot.confidence_high}},
          {"rollouts", shot.rollouts}};
}
}  // namespace

Expected<json> solvePlanShot(const json& request, const SolverOptions& options)
{
  auto configuration = configurationOf(request, options);
  if (!configuration)
    return configuration.error();
  auto plan_request = planRequest(request, configuration.value().ball_radius);
  if (!plan_request)
    return plan_request.error();
  auto plan = planShot(plan_request.value(), configuration.value());
  if (!plan)
    return inRequestTerms(plan.error());
  const ShotPlan& p = plan.value();
  json answer = shotJson(p.best);
  answer["found"] = p.found;
  answer["evaluations"] = p.evaluations;
  answer["time_ms"] = p.seconds * 1e3;
  answer["alternatives"] = json::array();
  for (const PlannedShot& shot : p.alternatives)
    answer["alternatives"].push_back(shotJson(shot));
  if (!p.found)
    answer["explanation"] = p.explanation;
  if (!p.outcome.table.balls.empty())
  {
    TableTrajectory table = p.outcome.table;
    table.ids[0] = plan_request.value().cue_ball;  // the prediction calls the cue ball CUE_BALL_ID
    answer["outcome"] = tableJson(table, 0, MotionSetup{}, false);
    answer["outcome"]["strike"] = cueStrikeJson(p.outcome.strike, table.ids);
  }
  else
    answer["outcome"] = nullptr;
  return answer;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
