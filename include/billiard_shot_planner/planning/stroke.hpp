#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// A stroke in this package's convention (scenarios/cue_stroke.hpp; pooltool's and FastFiz's differ in signs, units
/// and frames: stroke_conventions.hpp): the cue's direction φ in the
/// cloth plane (counter-clockwise from +x), its elevation θ, its speed, and the hit point's offsets a (right, seen
/// along the cue) and b (up) from the ball's centre in ball radii.
struct Stroke
{
  double phi = 0.0;    ///< rad
  double theta = 0.0;  ///< rad
  double speed = 1.0;  ///< m/s, the cue's
  double a = 0.0;      ///< ball radii
  double b = 0.0;      ///< ball radii
};

/// The cue placement of a stroke on the ball whose centre is at `ball` on the cloth: the tip touches the ball at
/// the hit point, moving along the cue. Errors as strokeGeometry's.
Expected<CuePlacement> placeStroke(const Stroke& stroke, const Eigen::Vector2d& ball, double radius);

}  // namespace billiard_shot_planner
