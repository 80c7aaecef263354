#include "cue_control_markers.hpp"

#include <visualization_msgs/InteractiveMarkerControl.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/scenarios/cue_stroke.hpp"

namespace billiard_shot_planner
{
namespace
{
using visualization_msgs::InteractiveMarker;
using visualization_msgs::InteractiveMarkerControl;
using visualization_msgs::Marker;

constexpr double CUE_LENGTH = 1.2;      // m, drawn behind the tip
constexpr double CUE_DIAMETER = 0.013;  // m
constexpr double TIP_GAP = 0.004;       // m between the drawn tip and the ball, so that both stay visible

Eigen::Quaterniond aimOrientation(const Stroke& stroke)
{
  // Rz(φ) Ry(θ) takes x to the cue's direction of motion (cos θ cos φ, cos θ sin φ, −sin θ).
  return Eigen::AngleAxisd(stroke.phi, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(stroke.theta, Eigen::Vector3d::UnitY());
}

Eigen::Vector3d ballCentre(const CueHandles& handles)
{
  return Eigen::Vector3d(handles.ball.x(), handles.ball.y(), handles.radius);
}

Eigen::Vector3d cueDirection(const Stroke& stroke)
{
  return aimOrientation(stroke) * Eigen::Vector3d::UnitX();
}

/// The hit point: the hit normal does not depend on the elevation, and a hit point within MAX_HANDLE_OFFSET is on
/// the ball, so the elevation 0 always has one.
Eigen::Vector3d hitPoint(const CueHandles& handles)
{
  const Stroke& s = handles.stroke;
  return ballCentre(handles) + handles.radius * strokeGeometry({s.phi, 0.0, s.a, s.b}).value().hit_normal;
}

geometry_msgs::Pose pose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation)
{
  geometry_msgs::Pose p;
  p.position.x = position.x();
  p.position.y = position.y();
  p.position.z = position.z();
  p.orientation.w = orientation.w();
  p.orientation.x = orientation.x();
  p.orientation.y = orientation.y();
  p.orientation.z = orientation.z();
  return p;
}

/// A control about or along its x axis, turned so that x becomes `axis` of the marker (or of the table: FIXED).
InteractiveMarkerControl control(const std::string& name, uint8_t mode, const Eigen::Quaterniond& x_to_axis,
                                 uint8_t orientation_mode)
{
  InteractiveMarkerControl c;
  c.name = name;
  c.interaction_mode = mode;
  c.orientation_mode = orientation_mode;
  c.orientation.w = x_to_axis.w();
  c.orientation.x = x_to_axis.x();
  c.orientation.y = x_to_axis.y();
  c.orientation.z = x_to_axis.z();
  return c;
}

Marker shape(uint8_t type, const Eigen::Vector3d& scale, float r, float g, float b)
{
  Marker m;
  m.type = type;
  m.scale.x = scale.x();
  m.scale.y = scale.y();
  m.scale.z = scale.z();
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = 1.0f;
  m.pose.orientation.w = 1.0;
  return m;
}

/// The cue, drawn in the aim marker's frame (x along the cue) behind the hit point.
InteractiveMarkerControl cueDrawing(const CueHandles& handles)
{
  const Eigen::Quaterniond aim = aimOrientation(handles.stroke);
  const Eigen::Vector3d tip = aim.inverse() * (hitPoint(handles) - ballCentre(handles));
  Marker cue = shape(Marker::CYLINDER, {CUE_DIAMETER, CUE_DIAMETER, CUE_LENGTH}, 0.75f, 0.55f, 0.3f);
  const Eigen::Quaterniond z_to_x(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()));
  cue.pose = pose(tip - (TIP_GAP + 0.5 * CUE_LENGTH) * Eigen::Vector3d::UnitX(), z_to_x);
  InteractiveMarkerControl drawing;
  drawing.name = "cue";
  drawing.interaction_mode = InteractiveMarkerControl::NONE;
  drawing.always_visible = true;
  drawing.markers.push_back(cue);
  return drawing;
}

/// A handle named `name` in `frame` at `at`, drawn `scale` m large.
InteractiveMarker handle(const char* name, const char* description, float scale, const std::string& frame,
                         const geometry_msgs::Pose& at)
{
  InteractiveMarker m;
  m.header.frame_id = frame;
  m.name = name;
  m.description = description;
  m.scale = scale;
  m.pose = at;
  return m;
}

/// A control that moves its handle in `mode` (along or across its x axis), always drawn as `shown`.
InteractiveMarkerControl dragged(const std::string& name, uint8_t mode, const Marker& shown)
{
  InteractiveMarkerControl c = control(name, mode, Eigen::Quaterniond::Identity(), InteractiveMarkerControl::INHERIT);
  c.always_visible = true;
  c.markers.push_back(shown);
  return c;
}

InteractiveMarker aimMarker(const CueHandles& handles, const std::string& frame)
{
  InteractiveMarker m = handle(AIM_HANDLE, "aim: turn about the ball, raise the cue", 0.3f, frame,
                               pose(ballCentre(handles), aimOrientation(handles.stroke)));
  const Eigen::Quaterniond x_to_z(Eigen::AngleAxisd(-0.5 * M_PI, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond x_to_y(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()));
  m.controls.push_back(cueDrawing(handles));
  m.controls.push_back(control("turn", InteractiveMarkerControl::ROTATE_AXIS, x_to_z, InteractiveMarkerControl::FIXED));
  m.controls.push_back(
      control("raise", InteractiveMarkerControl::ROTATE_AXIS, x_to_y, InteractiveMarkerControl::INHERIT));
  return m;
}

InteractiveMarker tipMarker(const CueHandles& handles, const std::string& frame)
{
  // x along the cue's horizontal direction: the control's plane (normal x) is the ball's face seen by the player.
  const Eigen::Quaterniond facing(Eigen::AngleAxisd(handles.stroke.phi, Eigen::Vector3d::UnitZ()));
  InteractiveMarker m =
      handle(TIP_HANDLE, "tip: the hit point on the ball", 0.06f, frame, pose(hitPoint(handles), facing));
  const double dot = 0.3 * handles.radius;
  m.controls.push_back(
      dragged("move", InteractiveMarkerControl::MOVE_PLANE, shape(Marker::SPHERE, {dot, dot, dot}, 1.0f, 0.1f, 0.1f)));
  return m;
}

InteractiveMarker speedMarker(const CueHandles& handles, const std::string& frame)
{
  const Eigen::Vector3d behind =
      hitPoint(handles) - handles.speed_scale * handles.stroke.speed * cueDirection(handles.stroke);
  InteractiveMarker m = handle(SPEED_HANDLE, "speed: pull back along the cue", 0.12f, frame,
                               pose(behind, aimOrientation(handles.stroke)));
  m.controls.push_back(
      dragged("pull", InteractiveMarkerControl::MOVE_AXIS, shape(Marker::CUBE, {0.02, 0.04, 0.04}, 0.2f, 0.8f, 0.2f)));
  return m;
}

Eigen::Vector3d position(const geometry_msgs::Pose& p)
{
  return {p.position.x, p.position.y, p.position.z};
}
}  // namespace

std::vector<InteractiveMarker> cueHandleMarkers(const CueHandles& handles, const std::string& frame)
{
  return {aimMarker(handles, frame), tipMarker(handles, frame), speedMarker(handles, frame)};
}

Stroke strokeAfterDrag(const CueHandles& handles, const std::string& marker, const geometry_msgs::Pose& pose)
{
  Stroke stroke = handles.stroke;
  if (marker == AIM_HANDLE)
  {
    const auto& q = pose.orientation;
    const Eigen::Vector3d d = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * Eigen::Vector3d::UnitX();
    stroke.phi = std::atan2(d.y(), d.x());
    stroke.theta = std::clamp(std::atan2(-d.z(), std::hypot(d.x(), d.y())), 0.0, MAX_HANDLE_ELEVATION);
  }
  else if (marker == TIP_HANDLE)
  {
    const Eigen::Vector3d offset = (position(pose) - ballCentre(handles)) / handles.radius;
    const Eigen::Vector2d ab(offset.dot(Eigen::Vector3d(std::sin(stroke.phi), -std::cos(stroke.phi), 0.0)), offset.z());
    const Eigen::Vector2d within =
        ab.norm() > MAX_HANDLE_OFFSET ? Eigen::Vector2d(MAX_HANDLE_OFFSET * ab.normalized()) : ab;
    stroke.a = within.x();
    stroke.b = within.y();
  }
  else if (marker == SPEED_HANDLE)
  {
    const double behind = (hitPoint(handles) - position(pose)).dot(cueDirection(stroke));
    stroke.speed = std::clamp(behind / handles.speed_scale, MIN_HANDLE_SPEED, MAX_HANDLE_SPEED);
  }
  // A pose of NaNs (a client's, not rviz's) leaves the cue where it was.
  const bool finite = std::isfinite(stroke.phi) && std::isfinite(stroke.theta) && std::isfinite(stroke.speed) &&
                      std::isfinite(stroke.a) && std::isfinite(stroke.b);
  return finite ? stroke : handles.stroke;
}

}  // namespace billiard_shot_planner
