#include "trajectory_markers.hpp"

#include "geometry_conversions.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

#include "billiard_shot_planner/motion/table_outline.hpp"

namespace billiard_shot_planner
{
namespace
{
using visualization_msgs::Marker;

std_msgs::ColorRGBA rgba(float r, float g, float b, float a = 1.0f)
{
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

/// A marker of one meaning: its own namespace, identity orientation, forever until the next DELETEALL.
Marker marker(const std::string& frame, const std::string& ns, int id, int type)
{
  Marker m;
  m.header.frame_id = frame;
  m.header.stamp = ros::Time(0);
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  return m;
}

Marker sphere(const std::string& frame, const std::string& ns, const Eigen::Vector3d& centre, double diameter,
              const std_msgs::ColorRGBA& colour)
{
  Marker m = marker(frame, ns, 0, Marker::SPHERE);
  m.pose.position = toPoint(centre);
  m.scale.x = m.scale.y = m.scale.z = diameter;
  m.color = colour;
  return m;
}

Marker arrow(const std::string& frame, const std::string& ns, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
             const std_msgs::ColorRGBA& colour)
{
  Marker m = marker(frame, ns, 0, Marker::ARROW);
  m.points = {toPoint(from), toPoint(to)};
  m.scale.x = 0.006;  // shaft diameter
  m.scale.y = 0.012;  // head diameter
  m.scale.z = 0.0;    // head length: rviz's default share
  m.color = colour;
  return m;
}

Marker path(const ShotOutcome& outcome, const std::string& frame, double spacing, const MarkerStyle& style)
{
  Marker m = marker(frame, "trajectory", 0, Marker::LINE_STRIP);
  m.scale.x = style.path_width;
  m.color = phaseColour(MotionPhase::Sliding);
  for (const TrajectorySample& s : outcome.trajectory.sample(spacing))
  {
    m.points.push_back(toPoint(s.state.position));
    m.colors.push_back(phaseColour(s.phase));
  }
  if (m.points.size() == 1)  // a LINE_STRIP needs two points
  {
    m.points.push_back(m.points.front());
    m.colors.push_back(m.colors.front());
  }
  return m;
}

Marker cue(const ShotOutcome& outcome, const std::string& frame, const MarkerStyle& style)
{
  // A cylinder along −ĉ behind the tip; the marker's z axis is the cylinder's axis.
  Marker m = marker(frame, "cue", 0, Marker::CYLINDER);
  const Eigen::Vector3d c = outcome.strike.cue_direction;
  const Eigen::Vector3d tip = outcome.hit_point;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), -c);
  m.pose.position = toPoint(tip - 0.5 * style.cue_length * c);
  m.pose.orientation.x = q.x();
  m.pose.orientation.y = q.y();
  m.pose.orientation.z = q.z();
  m.pose.orientation.w = q.w();
  m.scale.x = m.scale.y = style.cue_diameter;
  m.scale.z = style.cue_length;
  m.color = rgba(0.85f, 0.7f, 0.45f);
  return m;
}

Marker events(const ShotOutcome& outcome, const std::string& frame)
{
  Marker m = marker(frame, "events", 0, Marker::SPHERE_LIST);
  m.scale.x = m.scale.y = m.scale.z = 0.015;
  m.color = rgba(1.0f, 1.0f, 0.0f);
  for (const MotionEvent& e : outcome.trajectory.events)
    m.points.push_back(toPoint(e.state.position));
  return m;
}

/// A colour of its own for object ball k (k ≥ 1), distinct from the phase colours of the cue ball's path.
std_msgs::ColorRGBA ballColour(std::size_t k)
{
  static const std_msgs::ColorRGBA palette[] = {
      rgba(1.0f, 0.85f, 0.0f), rgba(0.1f, 0.3f, 1.0f), rgba(1.0f, 0.1f, 0.1f),  rgba(0.55f, 0.0f, 0.8f),
      rgba(1.0f, 0.45f, 0.0f), rgba(0.0f, 0.6f, 0.1f), rgba(0.6f, 0.25f, 0.1f), rgba(0.15f, 0.15f, 0.15f)};
  return palette[(k - 1) % (sizeof(palette) / sizeof(palette[0]))];
}

/// Object ball k's path (k ≥ 1: the cue ball's is drawn by phase), its start, its id and, when pocketed, a ring.
void addObjectBall(visualization_msgs::MarkerArray& array, const ShotOutcome& outcome, std::size_t k,
                   const std::string& frame, double spacing, double diameter, const MarkerStyle& style)
{
  const BallTrajectory& ball = outcome.table.balls[k];
  const int id = static_cast<int>(k);
  Marker line = marker(frame, "object_paths", id, Marker::LINE_STRIP);
  line.scale.x = style.path_width;
  line.color = ballColour(k);
  for (const TrajectorySample& s : ball.sample(spacing))
    line.points.push_back(toPoint(s.state.position));
  while (line.points.size() < 2)  // a LINE_STRIP needs two points (a ball that never moves)
    line.points.push_back(toPoint(ball.events.front().state.position));
  array.markers.push_back(line);
  Marker start = sphere(frame, "object_balls", ball.events.front().state.position, diameter, ballColour(k));
  start.id = id;
  array.markers.push_back(start);
  Marker label = marker(frame, "object_ids", id, Marker::TEXT_VIEW_FACING);
  label.pose.position = toPoint(ball.events.front().state.position + Eigen::Vector3d(0, 0, 2.0 * diameter));
  label.scale.z = diameter;
  label.color = rgba(1.0f, 1.0f, 1.0f);
  label.text = outcome.table.ids[k];
  array.markers.push_back(label);
  if (ball.outcome == MotionOutcome::Pocketed)
  {
    Marker dropped =
        sphere(frame, "pocketed", ball.finalState().position, 1.6 * diameter, rgba(1.0f, 0.0f, 0.0f, 0.4f));
    dropped.id = id;
    array.markers.push_back(dropped);
  }
}

/// The ghost ball: where the cue ball is when it first touches another ball.
void addGhostBall(visualization_msgs::MarkerArray& array, const ShotOutcome& outcome, const std::string& frame,
                  double diameter)
{
  for (const MotionEvent& e : outcome.trajectory.events)
    if (e.type == MotionEventType::BallCollision)
    {
      array.markers.push_back(
          sphere(frame, "ghost_ball", outcome.trajectory.at(e.time).position, diameter, rgba(1.0f, 1.0f, 1.0f, 0.3f)));
      return;
    }
}

/// The balls of the strike's impact, for a cue ball that touches others: a line joining each touching pair at the
/// balls' height, and each other ball's velocity right after the strike.
void addStrikeContacts(visualization_msgs::MarkerArray& array, const ShotOutcome& outcome, const std::string& frame,
                       const MarkerStyle& style)
{
  if (outcome.strike.touching_balls.empty())
    return;
  const auto start = [&](std::size_t ball) { return outcome.table.balls[ball].events.front().state.position; };
  Marker pairs = marker(frame, "strike_contacts", 0, Marker::LINE_LIST);
  pairs.scale.x = 0.01;
  pairs.color = rgba(1.0f, 0.3f, 0.0f);
  for (const TouchingBalls& pair : outcome.strike.touching_balls)
    if (std::max(pair.first, pair.second) < outcome.table.balls.size())
      pairs.points.insert(pairs.points.end(), {toPoint(start(pair.first)), toPoint(start(pair.second))});
  array.markers.push_back(pairs);
  int id = 0;
  for (const StruckBall& ball : outcome.strike.other_balls)
  {
    if (ball.ball >= outcome.table.balls.size())
      continue;
    Marker velocity = arrow(frame, "strike_velocity", start(ball.ball),
                            start(ball.ball) + style.velocity_scale * ball.velocity, rgba(1.0f, 1.0f, 0.0f));
    velocity.id = id++;
    array.markers.push_back(velocity);
  }
}

void addTable(visualization_msgs::MarkerArray& array, const Table& table, const std::string& frame)
{
  Marker cloth = marker(frame, "table", 0, Marker::CUBE);
  cloth.pose.position.z = -0.0025;
  cloth.scale.x = table.length;
  cloth.scale.y = table.width;
  cloth.scale.z = 0.005;
  cloth.color = rgba(0.05f, 0.35f, 0.15f);
  array.markers.push_back(cloth);

  // The cushions as the table's outline lays them out: a block behind each straight nose (rails and jaw facings),
  // a line along each rounded jaw point. A table the outline refuses was refused before it was drawn.
  const auto outline = tableOutline(table);
  if (!outline)
    return;
  const double rail = 0.05;  // m, drawn depth of a cushion behind its nose
  int block_id = 0, point_id = 0;
  for (const NoseSegment& segment : outline.value().cushions)
  {
    if (segment.shape == NoseSegment::Shape::Arc)
    {
      Marker point = marker(frame, "jaw_points", point_id++, Marker::LINE_STRIP);
      point.scale.x = 0.004;
      point.color = rgba(0.35f, 0.2f, 0.1f);
      const Eigen::Vector2d from = segment.start - segment.centre;
      for (int k = 0; k <= 8; ++k)
      {
        const Eigen::Vector2d at = segment.centre + Eigen::Rotation2Dd(segment.sweep * k / 8.0) * from;
        point.points.push_back(toPoint(Eigen::Vector3d(at.x(), at.y(), table.cushion_height)));
        point.colors.push_back(point.color);
      }
      array.markers.push_back(point);
      continue;
    }
    const Eigen::Vector2d along = segment.end - segment.start;
    const Eigen::Vector2d behind(along.y() / along.norm(), -along.x() / along.norm());  // the cloth is on the left
    const Eigen::Vector2d middle = 0.5 * (segment.start + segment.end) + 0.5 * rail * behind;
    Marker block = marker(frame, "cushions", block_id++, Marker::CUBE);
    block.pose.position.x = middle.x();
    block.pose.position.y = middle.y();
    block.pose.position.z = 0.5 * table.cushion_height;
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(std::atan2(along.y(), along.x()), Eigen::Vector3d::UnitZ()));
    block.pose.orientation.x = turn.x();
    block.pose.orientation.y = turn.y();
    block.pose.orientation.z = turn.z();
    block.pose.orientation.w = turn.w();
    block.scale.x = along.norm();
    block.scale.y = rail;
    block.scale.z = table.cushion_height;
    block.color = rgba(0.35f, 0.2f, 0.1f);
    array.markers.push_back(block);
  }
  // What the motion drops a ball into: the capture circles, or under the jaws' model the drop regions.
  std::vector<std::pair<Eigen::Vector2d, double>> holes;
  if (table.pocket_model == PocketModel::Jaws)
    for (const PocketOpening& opening : outline.value().pockets)
      holes.emplace_back(opening.drop_centre, opening.drop_radius);
  else
    for (const Pocket& capture : table.pockets)
      holes.emplace_back(capture.centre, capture.radius);
  for (std::size_t i = 0; i < holes.size(); ++i)
  {
    Marker pocket = marker(frame, "pockets", static_cast<int>(i), Marker::CYLINDER);
    pocket.pose.position.x = holes[i].first.x();
    pocket.pose.position.y = holes[i].first.y();
    pocket.pose.position.z = 0.001;
    pocket.scale.x = pocket.scale.y = 2.0 * holes[i].second;
    pocket.scale.z = 0.002;
    pocket.color = rgba(0.0f, 0.0f, 0.0f);
    array.markers.push_back(pocket);
  }
}
}  // namespace

std_msgs::ColorRGBA phaseColour(MotionPhase phase)
{
  switch (phase)
  {
    case MotionPhase::Airborne:
      return rgba(1.0f, 0.55f, 0.0f);  // orange
    case MotionPhase::Sliding:
      return rgba(1.0f, 0.0f, 1.0f);  // magenta
    case MotionPhase::Rolling:
      return rgba(0.0f, 1.0f, 1.0f);  // cyan
    case MotionPhase::Spinning:
    case MotionPhase::Stationary:
      break;
  }
  return rgba(1.0f, 1.0f, 1.0f);  // white
}

visualization_msgs::MarkerArray tableMarkers(const Table& table, const std::string& frame)
{
  visualization_msgs::MarkerArray array;
  Marker clear = marker(frame, "", 0, Marker::CUBE);
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);
  addTable(array, table, frame);
  return array;
}

visualization_msgs::MarkerArray trajectoryMarkers(const ShotOutcome& outcome, const ShotConfiguration& configuration,
                                                  const std::string& frame, double sample_spacing,
                                                  const MarkerStyle& style)
{
  visualization_msgs::MarkerArray array;
  Marker clear = marker(frame, "", 0, Marker::CUBE);
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);

  const double diameter = 2.0 * configuration.ball_radius;
  const Eigen::Vector3d start = outcome.trajectory.events.front().state.position;
  array.markers.push_back(path(outcome, frame, sample_spacing, style));
  array.markers.push_back(sphere(frame, "ball_start", start, diameter, rgba(1.0f, 1.0f, 1.0f)));
  array.markers.push_back(
      sphere(frame, "ball_end", outcome.trajectory.finalState().position, diameter, rgba(1.0f, 1.0f, 1.0f, 0.6f)));
  array.markers.push_back(
      arrow(frame, "velocity", start, start + style.velocity_scale * outcome.strike.velocity, rgba(1.0f, 1.0f, 0.0f)));
  array.markers.push_back(
      arrow(frame, "spin", start, start + style.spin_scale * outcome.strike.angular_velocity, rgba(0.2f, 0.4f, 1.0f)));
  array.markers.push_back(sphere(frame, "hit_point", outcome.hit_point, 0.01, rgba(1.0f, 0.0f, 0.0f)));
  array.markers.push_back(cue(outcome, frame, style));
  array.markers.push_back(events(outcome, frame));
  for (std::size_t k = 1; k < outcome.table.balls.size(); ++k)
    addObjectBall(array, outcome, k, frame, sample_spacing, diameter, style);
  addGhostBall(array, outcome, frame, diameter);
  addStrikeContacts(array, outcome, frame, style);
  addTable(array, configuration.table, frame);
  return array;
}

}  // namespace billiard_shot_planner
