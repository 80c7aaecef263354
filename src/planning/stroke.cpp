#include "billiard_shot_planner/planning/stroke.hpp"

#include "billiard_shot_planner/scenarios/cue_stroke.hpp"

namespace billiard_shot_planner
{
Expected<CuePlacement> placeStroke(const Stroke& stroke, const Eigen::Vector2d& ball, double radius)
{
  auto geometry = strokeGeometry({stroke.phi, stroke.theta, stroke.a, stroke.b});
  if (!geometry)
    return geometry.error();
  CuePlacement cue;
  cue.ball = ball;
  cue.direction = geometry.value().cue_direction;
  cue.tip = Eigen::Vector3d(ball.x(), ball.y(), radius) + radius * geometry.value().hit_normal;
  cue.speed = stroke.speed;
  return cue;
}

}  // namespace billiard_shot_planner
