#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// A stroke as players describe it (pooltool and FastFiz write it with other signs, units and frames:
/// planning/stroke_conventions.hpp). Table frame, z up; angles in
/// radians, offsets in ball radii.
///
/// The hit point lies on the near side of the ball at `a` to the right of its centre (as seen along the cue's
/// horizontal direction) and `b` above it; the cue's axis passes through it along ĉ = (cos θ cos φ, cos θ sin φ,
/// −sin θ). Positive `a` is right english (the ball spins counter-clockwise seen from above), positive `b` follow,
/// negative `b` draw.
struct CueStroke
{
  double phi = 0.0;    ///< the cue's direction in the cloth plane, counter-clockwise from +x
  double theta = 0.0;  ///< the cue's elevation above the cloth, [−π/2, π/2]; negative points up into the ball
  double a = 0.0;      ///< sideways offset of the hit point, + right; a² + b² < 1
  double b = 0.0;      ///< height offset of the hit point, + up
};

/// The direction of the cue's motion and the ball's outward normal at the hit point.
struct StrokeGeometry
{
  Eigen::Vector3d cue_direction;
  Eigen::Vector3d hit_normal;
};

/// Errors (fields "phi", "theta", "a", "b"): non-finite values, θ outside [−π/2, π/2], a hit point off the ball
/// (a² + b² ≥ 1), and, InvalidShot, a cue that cannot reach the hit point at that elevation without passing
/// through the ball (ĉ·n̂ ≥ 0: a steep cue below the equator).
Expected<StrokeGeometry> strokeGeometry(const CueStroke& stroke);

}  // namespace billiard_shot_planner
