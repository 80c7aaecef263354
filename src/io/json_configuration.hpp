#pragma once

// The physics of a request as a ShotConfiguration, shared by plan_shot and calibrate (json_configuration.cpp).
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
/// The strike's physics (cue_mass, ball_mass, ball_radius, stiffness_ratio, cue_end_mass, cue_contact,
/// table_contact), the table and motion (table_file, table, the ball_motion options) and ball_ball of a request,
/// as table_shot reads them.
Expected<ShotConfiguration> configurationOf(const json& request, const SolverOptions& options);

}  // namespace json_io
}  // namespace billiard_shot_planner
