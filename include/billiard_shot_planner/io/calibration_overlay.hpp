#pragma once

#include <string>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

namespace billiard_shot_planner
{
/// A fit's identifiable parameters as a parameter file for the node: nested maps under the steps of their names
/// ("table.cushion.restitution" → table: cushion: restitution:), headed by the comment `origin`, to load after the
/// defaults as launch/predict_shot.launch loads config/paper_masse.yaml.
std::string calibrationOverlayYaml(const FitResult& fit, const std::string& origin);

}  // namespace billiard_shot_planner
