#include "trajectory_markers.hpp"

#include "geometry_conversions.hpp"

#include <Eigen/Geometry>

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

void addTable(visualization_msgs::MarkerArray& array, const Table& table, const std::string& frame)
{
  Marker cloth = marker(frame, "table", 0, Marker::CUBE);
  cloth.pose.position.z = -0.0025;
  cloth.scale.x = table.length;
  cloth.scale.y = table.width;
  cloth.scale.z = 0.005;
  cloth.color = rgba(0.05f, 0.35f, 0.15f);
  array.markers.push_back(cloth);

  const double rail = 0.05;  // m, drawn width of a cushion
  for (int i = 0; i < 4; ++i)
  {
    Marker cushion = marker(frame, "cushions", i, Marker::CUBE);
    const int axis = i / 2;
    const double side = i % 2 == 0 ? -1.0 : 1.0;
    const double half = 0.5 * (axis == 0 ? table.length : table.width);
    cushion.pose.position.x = axis == 0 ? side * (half + 0.5 * rail) : 0.0;
    cushion.pose.position.y = axis == 1 ? side * (half + 0.5 * rail) : 0.0;
    cushion.pose.position.z = 0.5 * table.cushion_height;
    cushion.scale.x = axis == 0 ? rail : table.length + 2 * rail;
    cushion.scale.y = axis == 1 ? rail : table.width;
    cushion.scale.z = table.cushion_height;
    cushion.color = rgba(0.35f, 0.2f, 0.1f);
    array.markers.push_back(cushion);
  }
  for (std::size_t i = 0; i < table.pockets.size(); ++i)
  {
    Marker pocket = marker(frame, "pockets", static_cast<int>(i), Marker::CYLINDER);
    pocket.pose.position.x = table.pockets[i].centre.x();
    pocket.pose.position.y = table.pockets[i].centre.y();
    pocket.pose.position.z = 0.001;
    pocket.scale.x = pocket.scale.y = 2.0 * table.pockets[i].radius;
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
  addTable(array, configuration.table, frame);
  return array;
}

}  // namespace billiard_shot_planner
