#pragma once

#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The parameters' own start, then count − 1 points of a Halton sequence over their bounds: log-uniform where a
/// positive range spans more than a factor of ten, uniform where it is finite, the start where it is not.
std::vector<std::vector<double>> startingPoints(const std::vector<FitParameter>& parameters, int count);

}  // namespace detail
}  // namespace billiard_shot_planner
