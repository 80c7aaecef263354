#pragma once

// Reading and writing the JSON of impact_solve: typed field access whose errors name the field.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/laws/normal_law.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/io/table_yaml.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
using nlohmann::json;

/// object[key] as a number; `fallback` when absent (required when there is none).
Expected<double> number(const json& object, const std::string& key, std::optional<double> fallback = std::nullopt);
/// Reads several numbers into their targets. Optional fields keep the target's value when absent; errors get
/// `prefix` ("table.cloth.friction").
enum class Presence
{
  Optional,
  Required,
};
Status readNumbers(const json& object, std::initializer_list<std::pair<const char*, double*>> fields,
                   const std::string& prefix = "", Presence presence = Presence::Optional);
/// object[key] as an array of numbers.
Expected<std::vector<double>> numbers(const json& object, const std::string& key);
/// object[key] as [x, y, z]; `fallback` when absent.
Expected<Eigen::Vector3d> vector3(const json& object, const std::string& key,
                                  std::optional<Eigen::Vector3d> fallback = std::nullopt);
/// A contact's constants: {"restitution", "friction", "eta2", "law": {"type", <parameters>}} read from `fields`
/// into `surface`; with Presence::Optional each keeps the surface's value when absent. Errors name `prefix`.<field>,
/// a law's unknown type or parameter included (docs/extending.md lists the laws).
Status readSurfaceContact(const json& fields, const std::string& prefix, SurfaceContact& surface,
                          Presence presence = Presence::Optional, std::initializer_list<const char*> also_known = {});
/// Refuses a key of `object` that neither `known` nor `also_known` lists: a misspelt constant is an error, not a
/// default. The error names `prefix`.<key>.
Status onlyKnownKeys(const json& object, std::initializer_list<const char*> known, const std::string& prefix,
                     std::initializer_list<const char*> also_known = {});
/// The stroke of a "cue" object {"phi_deg", "theta_deg", "speed", "a", "b", "convention"} (`prefix`: its field's
/// name): in this package's convention, or, with "convention": "pooltool" or "fastfiz", in theirs (degrees, their
/// signs and frames; FastFiz's a and b in millimetres of `ball_radius`), converted. Unknown keys are refused.
Expected<Stroke> strokeFromJson(const json& cue, const std::string& prefix, double ball_radius);
/// The request's "table_file" (config/tables/snooker_mathavan.yaml): the table, its balls, its ball–ball contact and
/// its cloth's motion constants, which the request's own fields override. Call only when the request has one.
Expected<TableFile> tableFile(const json& request);
/// "law": {"type": "elastic_plastic", "yield_speed": 1.2} over `base` (the contact's law so far): a type other than
/// base's starts from its defaults, the same type (or none given) keeps base's parameters, and the given ones
/// replace them; unknown keys refused, a parameter the law lacks named as such.
Expected<NormalLaw> normalLawFromJson(const json& law, const std::string& prefix, const NormalLaw& base = {});
/// The law as normalLawFromJson reads it.
json normalLawJson(NormalLaw law);
/// object[key] as an object (an empty one when absent and optional).
Expected<json> object(const json& parent, const std::string& key, bool required);
/// The optional "solver" object.
Expected<SolverOptions> solverOptions(const json& request);
/// A "ball_ball" object's friction model: "alciatore" goes without a "friction", "constant" with one (docs/cli.md).
Status checkFrictionModel(const json& ball_ball);
/// An error from a nested object, its field prefixed with the object's name ("cue_contact.friction").
Error nested(const std::string& prefix, Error error);

std::vector<double> toVector(const Eigen::VectorXd& v);
json snapshotJson(const ImpactSnapshot& snap);
/// events, ends_of_compression, converged, energy, samples: what every problem reports the same way.
json commonResultJson(const ImpactResult& result, const std::vector<std::string>& contact_names = {});

/// The ball–ball contact of a table: "ball_ball": {"restitution", "friction" or "friction_model": "alciatore",
/// "eta2", "cloth_stiffness_ratio"}, each optional (json_collisions.cpp).
Expected<BallContactSettings> ballContactFromJson(const json& request);

/// The problems, one function each (json_collisions.cpp, json_strike.cpp).
Expected<json> solveBallBallTable(const json& request, const SolverOptions& options);
Expected<json> solveChain(const json& request, const SolverOptions& options);
Expected<json> solveBallBall(const json& request, const SolverOptions& options);
Expected<json> solveCueStrike(const json& request, const SolverOptions& options);
Expected<json> solveBallTable(const json& request, const SolverOptions& options);
Expected<json> solveBallMotion(const json& request, const SolverOptions& options);
Expected<json> solveShot(const json& request, const SolverOptions& options);
Expected<json> solveTableShot(const json& request, const SolverOptions& options);
Expected<json> solvePlanShot(const json& request, const SolverOptions& options);
Expected<json> solveCalibrate(const json& request, const SolverOptions& options);

/// The cue strike fields of a request (json_strike.cpp), the strike solved, and its result as JSON.
Expected<CueStrike> cueStrikeFromJson(const json& request);
/// The same without the cue (its direction, speed and hit point): masses, contacts and the stiffness ratio.
Expected<CueStrike> strikePhysicsFromJson(const json& request);
struct StrikeAnswer
{
  CueStrike strike;
  CueStrikeResult result;
};
Expected<StrikeAnswer> solveStrikeFromJson(const json& request, const SolverOptions& options);
/// The strike as JSON: the struck ball's state, the engine's record, every contact by name with its impulse
/// ("contacts"), the other balls it moved ("other_balls") and the touching pairs ("touching"), balls named by `ids`
/// (by index where none are given).
json cueStrikeJson(const CueStrikeResult& result, const std::vector<std::string>& ids = {});

}  // namespace json_io
}  // namespace billiard_shot_planner
