#pragma once

#include <vector>

#include "billiard_shot_planner/motion/table_simulation.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The simulation of simulateTable on input already checked (predictTrajectory checks its one ball itself, to name
/// its fields as a lone ball's).
Expected<TableTrajectory> runTableSimulation(const std::vector<TableBall>& balls, const BallProperties& ball,
                                             const Table& table, const MotionParameters& parameters,
                                             const BallContactSettings& contact);
}  // namespace detail
}  // namespace billiard_shot_planner
