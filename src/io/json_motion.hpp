#pragma once

// The motion parts of impact_solve's JSON, shared by ball_motion, shot and table_shot (json_motion.cpp).
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
using nlohmann::json;

/// Everything but the start state: ball, table and motion parameters, and the sample spacing.
struct MotionSetup
{
  BallProperties ball;
  Table table;
  MotionParameters parameters;
  double spacing = 0.01;
};

/// The ball ("ball_mass", "ball_radius"), the table ("table_file", "table", or the strike's "table_contact" as its
/// cloth), the motion parameters and "sample_spacing" of a request.
Expected<MotionSetup> motionSetup(const json& request, const SolverOptions& options);
/// The strike of a request (its cue fields) and the table and motion it moves on, all read before anything is
/// solved: bad input costs nothing.
struct StrikeSetup
{
  CueStrike strike;
  MotionSetup motion;
};
Expected<StrikeSetup> strikeSetup(const json& request, const SolverOptions& options);
/// The table and motion of a request read after `strike` (its fields already read, or its error passed on).
Expected<StrikeSetup> withMotion(Expected<CueStrike> strike, const json& request, const SolverOptions& options);
/// object[key] as [x, y].
Expected<Eigen::Vector2d> vector2(const json& object, const std::string& key);
/// A ball on the cloth from {"position": [x, y], "v": [x, y, z], "omega": [x, y, z]} (v and omega default to 0;
/// the centre at height `radius`); errors name the field after `prefix` ("balls[2].position").
Expected<BallState> ballOnCloth(const json& fields, const std::string& prefix, double radius);
std::vector<double> toVector3(const Eigen::Vector3d& v);
json stateJson(const BallState& state);
/// {t, type, position, v, omega, cushion?, pocket?}
json eventJson(const MotionEvent& event);
}  // namespace json_io
}  // namespace billiard_shot_planner
