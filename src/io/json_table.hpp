#pragma once

// The table parts of impact_solve's JSON, shared by table_shot and plan_shot (json_table.cpp).
#include <string>
#include <vector>

#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "json_motion.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
/// "balls": [{"id", "position": [x, y], "v", "omega"}, …] (at most MAX_TABLE_BALLS + 1 read: the table refuses
/// more); errors name the ball ("balls[2].id").
Expected<std::vector<TableBall>> tableBalls(const json& request, double radius);
/// The index of the ball named by "cue_ball" (default "cue").
Expected<std::size_t> cueBallIndex(const json& request, const std::vector<TableBall>& balls);
/// balls (id, outcome, pocket, final_position, events, samples when asked), first_contact, pocketed, collisions,
/// duration: the table_shot answer without its strike.
json tableJson(const TableTrajectory& run, std::size_t cue, const MotionSetup& setup, bool samples);
}  // namespace json_io
}  // namespace billiard_shot_planner
