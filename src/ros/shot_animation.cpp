#include "shot_animation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
namespace
{
constexpr double GRAVITY = 9.81;  // m/s^2: a pocketed ball's fall

/// The path's position at `time`, held at its ends.
geometry_msgs::Point positionAt(const std::vector<PathSample>& path, double time)
{
  if (time <= path.front().time)
    return path.front().position;
  if (time >= path.back().time)
    return path.back().position;
  const auto after = std::upper_bound(path.begin(), path.end(), time,
                                      [](double t, const PathSample& sample) { return t < sample.time; });
  const PathSample& p = *(after - 1);
  const PathSample& q = *after;
  const double span = q.time - p.time;
  const double s = span > 0.0 ? (time - p.time) / span : 1.0;
  geometry_msgs::Point point;
  point.x = p.position.x + s * (q.position.x - p.position.x);
  point.y = p.position.y + s * (q.position.y - p.position.y);
  point.z = p.position.z + s * (q.position.z - p.position.z);
  return point;
}

visualization_msgs::Marker ballMarker(const ShotPrediction& prediction, std::size_t index, double ball_radius)
{
  visualization_msgs::Marker m;
  m.header.frame_id = prediction.header.frame_id;
  m.ns = "animation";
  m.id = static_cast<int>(index);
  m.type = visualization_msgs::Marker::SPHERE;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 2.0 * ball_radius;
  const bool cue_ball = prediction.balls[index].id == CUE_BALL_ID;
  m.color.r = 1.0f;
  m.color.g = cue_ball ? 1.0f : 0.55f;
  m.color.b = cue_ball ? 1.0f : 0.1f;
  m.color.a = 1.0f;
  return m;
}
}  // namespace

visualization_msgs::MarkerArray animationFrame(const ShotPrediction& prediction, double time, double ball_radius)
{
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker clear;
  clear.header.frame_id = prediction.header.frame_id;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);
  for (std::size_t i = 0; i < prediction.balls.size(); ++i)
  {
    const BallPrediction& ball = prediction.balls[i];
    if (ball.path.empty())
      continue;
    visualization_msgs::Marker m = ballMarker(prediction, i, ball_radius);
    m.pose.position = positionAt(ball.path, time);
    const double falling = time - ball.path.back().time;
    if (ball.outcome == "pocketed" && falling > 0.0)
    {
      if (falling > DROP_DURATION)
        continue;  // in the pocket
      m.pose.position.z -= 0.5 * GRAVITY * falling * falling;
    }
    array.markers.push_back(m);
  }
  return array;
}

Status checkAnimation(const ShotPrediction& prediction)
{
  for (std::size_t i = 0; i < prediction.balls.size(); ++i)
  {
    const std::string field = "prediction.balls[" + std::to_string(i) + "].path";
    const std::vector<PathSample>& path = prediction.balls[i].path;
    for (std::size_t k = 0; k < path.size(); ++k)
    {
      const auto& p = path[k].position;
      if (!std::isfinite(path[k].time) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return invalidArgument(field, "contains NaN or infinite values");
      if (k > 0 && path[k].time < path[k - 1].time)
        return invalidArgument(field, "times must not decrease");
    }
  }
  if (animationLength(prediction) > MAX_ANIMATION_LENGTH)
    return invalidArgument("prediction", "lasts longer than " + formatNumber(MAX_ANIMATION_LENGTH) + " s");
  return {};
}

double animationLength(const ShotPrediction& prediction)
{
  double length = 0.0;
  for (const BallPrediction& ball : prediction.balls)
    if (!ball.path.empty())
      length = std::max(length, ball.path.back().time + (ball.outcome == "pocketed" ? DROP_DURATION : 0.0));
  return length;
}

}  // namespace billiard_shot_planner
