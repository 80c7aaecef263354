#include <optional>
#include <string>

#include "billiard_shot_planner/io/table_yaml.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "json_fields.hpp"
#include "json_motion.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
std::vector<double> toVector3(const Eigen::Vector3d& v)
{
  return {v.x(), v.y(), v.z()};
}

Expected<Eigen::Vector2d> vector2(const json& object, const std::string& key)
{
  auto values = numbers(object, key);
  if (!values)
    return values.error();
  if (values.value().size() != 2)
    return invalidArgument(key, "must be [x, y]");
  return Eigen::Vector2d(values.value()[0], values.value()[1]);
}

Expected<BallState> ballOnCloth(const json& fields, const std::string& prefix, double radius)
{
  auto position = vector2(fields, "position");
  if (!position)
    return nested(prefix, position.error());
  auto velocity = vector3(fields, "v", Eigen::Vector3d::Zero());
  if (!velocity)
    return nested(prefix, velocity.error());
  auto spin = vector3(fields, "omega", Eigen::Vector3d::Zero());
  if (!spin)
    return nested(prefix, spin.error());
  BallState state;
  state.position << position.value(), radius;
  state.velocity = velocity.value();
  state.angular_velocity = spin.value();
  return state;
}

namespace
{
Expected<std::vector<Pocket>> pockets(const json& table)
{
  const json& list = table.at("pockets");
  if (!list.is_array())
    return invalidArgument("table.pockets", "must be an array of {\"centre\": [x, y], \"radius\": r}");
  std::vector<Pocket> out;
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const std::string name = "table.pockets[" + std::to_string(i) + "]";
    if (!list[i].is_object())
      return invalidArgument(name, "must be an object");
    auto centre = vector2(list[i], "centre");
    if (!centre)
      return nested(name, centre.error());
    auto radius = number(list[i], "radius");
    if (!radius)
      return nested(name, radius.error());
    out.push_back({centre.value(), radius.value()});
  }
  return out;
}

Status readSurface(const json& table, const char* key, SurfaceContact& surface)
{
  if (!table.contains(key))
    return {};
  if (!table.at(key).is_object())
    return invalidArgument(std::string("table.") + key, "must be an object");
  return readSurfaceContact(table.at(key), std::string("table.") + key, surface);
}

/// The request's "table" over the table file's (`file`, when the request names one) or over the defaults.
Expected<Table> tableField(const json& request, const SurfaceContact* cloth, const TableFile* file)
{
  Table table;
  if (file)
  {
    table = file->table;
  }
  else if (cloth)
  {
    table.cloth = *cloth;
  }
  auto fields = object(request, "table", false);
  if (!fields)
    return fields.error();
  const json& t = fields.value();
  if (Status known = onlyKnownKeys(
          t, {"length", "width", "cushion_height", "cushion_stiffness_ratio", "pockets", "cloth", "cushion"}, "table");
      !known)
    return known.error();
  if (Status status = readNumbers(t,
                                  {{"length", &table.length},
                                   {"width", &table.width},
                                   {"cushion_height", &table.cushion_height},
                                   {"cushion_stiffness_ratio", &table.cushion_stiffness_ratio}},
                                  "table");
      !status)
    return status.error();
  if (t.contains("length") || t.contains("width"))
    table.pockets = sixPockets(table.length, table.width);
  if (t.contains("pockets"))
  {
    auto list = pockets(t);
    if (!list)
      return list.error();
    table.pockets = list.value();
  }
  for (const char* key : {"cloth", "cushion"})
    if (Status status = readSurface(t, key, key == std::string("cloth") ? table.cloth : table.cushion); !status)
      return status.error();
  return table;
}

/// The request's motion fields over `base` (the table file's cloth friction, or the defaults).
Expected<MotionParameters> motionParameters(const json& request, const SolverOptions& options,
                                            const MotionParameters& base)
{
  MotionParameters p = base;
  p.impact = options;
  if (Status status = readNumbers(request, {{"gravity", &p.gravity},
                                            {"sliding_friction", &p.sliding_friction},
                                            {"rolling_friction", &p.rolling_friction},
                                            {"spinning_friction", &p.spinning_friction},
                                            {"min_bounce_speed", &p.min_bounce_speed},
                                            {"max_time", &p.max_time}});
      !status)
    return status.error();
  if (request.contains("planar"))
  {
    if (!request.at("planar").is_boolean())
      return invalidArgument("planar", "must be true or false");
    p.planar = request.at("planar").get<bool>();
  }
  if (request.contains("rolling_model"))
  {
    const json& given = request.at("rolling_model");
    auto model = rollingModelNamed(given.is_string() ? given.get<std::string>() : given.dump(), "rolling_model");
    if (!model)
      return model.error();
    p.rolling_model = model.value();
  }
  return p;
}

}  // namespace

json stateJson(const BallState& s)
{
  return json{
      {"position", toVector3(s.position)}, {"v", toVector3(s.velocity)}, {"omega", toVector3(s.angular_velocity)}};
}

json eventJson(const MotionEvent& e)
{
  json item = stateJson(e.state);
  item["t"] = e.time;
  item["type"] = toString(e.type);
  if (e.cushion >= 0)
    item["cushion"] = e.cushion;
  if (e.pocket >= 0)
    item["pocket"] = e.pocket;
  return item;
}

namespace
{
json trajectoryJson(const BallTrajectory& trajectory, double spacing)
{
  json events = json::array();
  for (const MotionEvent& e : trajectory.events)
    events.push_back(eventJson(e));
  json samples = json::array();
  for (const TrajectorySample& s : trajectory.sample(spacing))
    samples.push_back({{"t", s.time}, {"position", toVector3(s.state.position)}, {"phase", toString(s.phase)}});
  return json{{"events", events},
              {"samples", samples},
              {"outcome", toString(trajectory.outcome)},
              {"duration", trajectory.duration()},
              {"rest_position", toVector3(trajectory.finalState().position)}};
}

}  // namespace

Expected<MotionSetup> motionSetup(const json& request, const SolverOptions& options, const SurfaceContact* cloth,
                                  const BallProperties& ball)
{
  MotionSetup setup;
  setup.ball = ball;
  std::optional<TableFile> file;  // read once, for the table and the motion
  if (request.contains("table_file"))
  {
    auto loaded = tableFile(request);
    if (!loaded)
      return loaded.error();
    file = loaded.value();
  }
  auto table = tableField(request, cloth, file ? &*file : nullptr);
  if (!table)
    return table.error();
  setup.table = table.value();
  auto parameters = motionParameters(request, options, file ? file->motion : MotionParameters{});
  if (!parameters)
    return parameters.error();
  setup.parameters = parameters.value();
  if (Status status = readNumbers(request, {{"sample_spacing", &setup.spacing}}); !status)
    return status.error();
  if (!(setup.spacing >= 1e-4))
    return invalidArgument("sample_spacing", "must be at least 1e-4 s");
  return setup;
}

namespace
{
Expected<json> predict(const MotionSetup& setup, const Eigen::Vector2d& position, const Eigen::Vector3d& v,
                       const Eigen::Vector3d& omega)
{
  BallState start;
  start.position << position, setup.ball.radius;
  start.velocity = v;
  start.angular_velocity = omega;
  auto trajectory = predictTrajectory(start, setup.ball, setup.table, setup.parameters);
  if (!trajectory)
    return trajectory.error();
  return trajectoryJson(trajectory.value(), setup.spacing);
}
}  // namespace

Expected<json> solveBallMotion(const json& request, const SolverOptions& options)
{
  BallProperties ball;
  if (Status status = readNumbers(request, {{"ball_mass", &ball.mass}, {"ball_radius", &ball.radius}}); !status)
    return status.error();
  auto setup = motionSetup(request, options, nullptr, ball);
  if (!setup)
    return setup.error();
  auto position = vector2(request, "position");
  if (!position)
    return position.error();
  auto v = vector3(request, "v");
  if (!v)
    return v.error();
  auto omega = vector3(request, "omega");
  if (!omega)
    return omega.error();
  return predict(setup.value(), position.value(), v.value(), omega.value());
}

Expected<StrikeSetup> withMotion(Expected<CueStrike> strike, const json& request, const SolverOptions& options)
{
  if (!strike)
    return strike.error();
  CueStrike s = strike.value();
  auto setup = motionSetup(request, options, &s.table_contact, BallProperties{s.ball_mass, s.ball_radius});
  if (!setup)
    return setup.error();
  // A strike whose request omits its cloth contact stands on the table's cloth (a table file's, when given).
  if (!request.contains("table_contact"))
    s.table_contact = setup.value().table.cloth;
  return StrikeSetup{s, setup.value()};
}

Expected<StrikeSetup> strikeSetup(const json& request, const SolverOptions& options)
{
  return withMotion(cueStrikeFromJson(request), request, options);
}

Expected<json> solveShot(const json& request, const SolverOptions& options)
{
  auto setup = strikeSetup(request, options);
  if (!setup)
    return setup.error();
  const CueStrike& s = setup.value().strike;
  auto position = vector2(request, "ball_position");
  if (!position)
    return position.error();
  auto solved = solve(s, options);
  if (!solved)
    return solved.error();
  const CueStrikeResult& result = solved.value();
  auto trajectory = predict(setup.value().motion, position.value(), result.velocity, result.angular_velocity);
  if (!trajectory)
    return trajectory.error();
  return json{{"strike", cueStrikeJson(result)}, {"trajectory", trajectory.value()}};
}

}  // namespace json_io
}  // namespace billiard_shot_planner
