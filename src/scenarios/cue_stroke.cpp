#include "billiard_shot_planner/scenarios/cue_stroke.hpp"

#include <cmath>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
Expected<StrokeGeometry> strokeGeometry(const CueStroke& stroke)
{
  if (Status status = firstError({requireFinite(stroke.phi, "phi"), requireFinite(stroke.theta, "theta"),
                                  requireFinite(stroke.a, "a"), requireFinite(stroke.b, "b")});
      !status)
    return status.error();
  if (std::abs(stroke.theta) > 0.5 * M_PI)
    return invalidArgument("theta", "must be an elevation in [-90, 90] degrees");
  const double across = stroke.a * stroke.a + stroke.b * stroke.b;
  if (!(across < 1.0))
    return invalidArgument("a", "the hit point (a, b) must be on the ball: a^2 + b^2 < 1, got " + formatNumber(across));
  const Eigen::Vector3d forward(std::cos(stroke.phi), std::sin(stroke.phi), 0.0);
  const Eigen::Vector3d right(std::sin(stroke.phi), -std::cos(stroke.phi), 0.0);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  StrokeGeometry geometry;
  geometry.cue_direction = std::cos(stroke.theta) * forward - std::sin(stroke.theta) * up;
  geometry.hit_normal = stroke.a * right + stroke.b * up - std::sqrt(1.0 - across) * forward;
  const double approach = geometry.hit_normal.dot(geometry.cue_direction);
  if (!(approach < 0.0))
    return Error{ErrorKind::InvalidShot, "theta",
                 "at this elevation the cue cannot reach the hit point (a, b) without passing through the ball "
                 "(n.c = " +
                     formatNumber(approach) + " must be < 0)"};
  return geometry;
}

}  // namespace billiard_shot_planner
