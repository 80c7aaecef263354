#include <optional>
#include <string>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "json_configuration_reader.hpp"
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
  if (!e.cushion.empty())
    item["cushion"] = e.cushion;
  if (!e.pocket.empty())
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

Expected<MotionSetup> motionSetup(const json& request, const SolverOptions& options)
{
  auto configuration = requestConfiguration(request);
  if (!configuration)
    return configuration.error();
  const ShotConfiguration& c = configuration.value();
  MotionSetup setup;
  setup.ball = BallProperties{c.ball_mass, c.ball_radius};
  setup.table = c.table;
  setup.parameters = c.motion;
  setup.parameters.impact = options;
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
  auto setup = motionSetup(request, options);
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
  auto setup = motionSetup(request, options);
  if (!setup)
    return setup.error();
  return StrikeSetup{strike.value(), setup.value()};
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
