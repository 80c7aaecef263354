// The cockpit's cue handles: where cueHandleMarkers() puts them for a stroke, checked against the stroke's geometry
// written out here from docs/stroke_conventions.md (cue direction (cos θ cos φ, cos θ sin φ, −sin θ); hit point
// R (a·right + b·up − √(1 − a² − b²)·forward) from the centre), and strokeAfterDrag() reading each handle back.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "cue_control_markers.hpp"

namespace bsp = billiard_shot_planner;
using visualization_msgs::InteractiveMarker;

namespace
{
bsp::CueHandles handles()
{
  bsp::CueHandles h;
  h.stroke = {0.7, 0.3, 2.5, 0.2, -0.3};
  h.ball = Eigen::Vector2d(0.4, -0.2);
  h.radius = 0.028575;
  h.speed_scale = 0.1;
  return h;
}

Eigen::Vector3d centre(const bsp::CueHandles& h)
{
  return {h.ball.x(), h.ball.y(), h.radius};
}

Eigen::Vector3d hitPoint(const bsp::CueHandles& h)
{
  const bsp::Stroke& s = h.stroke;
  const Eigen::Vector3d forward(std::cos(s.phi), std::sin(s.phi), 0.0);
  const Eigen::Vector3d right(std::sin(s.phi), -std::cos(s.phi), 0.0);
  return centre(h) +
         h.radius * (s.a * right + s.b * Eigen::Vector3d::UnitZ() - std::sqrt(1.0 - s.a * s.a - s.b * s.b) * forward);
}

Eigen::Vector3d cueDirection(const bsp::Stroke& s)
{
  return {std::cos(s.theta) * std::cos(s.phi), std::cos(s.theta) * std::sin(s.phi), -std::sin(s.theta)};
}

Eigen::Vector3d position(const InteractiveMarker& m)
{
  return {m.pose.position.x, m.pose.position.y, m.pose.position.z};
}

Eigen::Quaterniond orientation(const InteractiveMarker& m)
{
  const auto& q = m.pose.orientation;
  return {q.w, q.x, q.y, q.z};
}

const InteractiveMarker& named(const std::vector<InteractiveMarker>& markers, const std::string& name)
{
  for (const InteractiveMarker& m : markers)
    if (m.name == name)
      return m;
  throw std::runtime_error("no marker " + name);
}
}  // namespace

TEST(CueHandles, TheAimSitsAtTheBallWithItsXAxisAlongTheCue)
{
  const bsp::CueHandles h = handles();
  const auto markers = bsp::cueHandleMarkers(h, "table");
  ASSERT_EQ(markers.size(), 3u);
  const InteractiveMarker& aim = named(markers, bsp::AIM_HANDLE);
  EXPECT_EQ(aim.header.frame_id, "table");
  EXPECT_LT((position(aim) - centre(h)).norm(), 1e-12);
  EXPECT_LT((orientation(aim) * Eigen::Vector3d::UnitX() - cueDirection(h.stroke)).norm(), 1e-12);
}

TEST(CueHandles, TheTipIsTheHitPointAndTheSpeedHandleIsBehindItAlongTheCue)
{
  const bsp::CueHandles h = handles();
  const auto markers = bsp::cueHandleMarkers(h, "table");
  EXPECT_LT((position(named(markers, bsp::TIP_HANDLE)) - hitPoint(h)).norm(), 1e-12);
  const Eigen::Vector3d behind = hitPoint(h) - h.speed_scale * h.stroke.speed * cueDirection(h.stroke);
  EXPECT_LT((position(named(markers, bsp::SPEED_HANDLE)) - behind).norm(), 1e-12);
}

TEST(CueHandles, EachHandleDraggedToAnotherStrokesPlaceReadsBackThatStroke)
{
  const bsp::CueHandles from = handles();
  bsp::CueHandles to = from;
  to.stroke = {-2.0, 0.9, 4.0, -0.5, 0.4};
  const auto target = bsp::cueHandleMarkers(to, "table");
  // The aim turns φ and θ only; the tip (dragged on the face of the new aim) moves a and b; the handle the speed.
  bsp::CueHandles aimed = from;
  aimed.stroke = bsp::strokeAfterDrag(from, bsp::AIM_HANDLE, named(target, bsp::AIM_HANDLE).pose);
  EXPECT_NEAR(aimed.stroke.phi, to.stroke.phi, 1e-12);
  EXPECT_NEAR(aimed.stroke.theta, to.stroke.theta, 1e-12);
  EXPECT_EQ(aimed.stroke.a, from.stroke.a);
  EXPECT_EQ(aimed.stroke.speed, from.stroke.speed);
  bsp::CueHandles tipped = aimed;
  tipped.stroke = bsp::strokeAfterDrag(aimed, bsp::TIP_HANDLE, named(target, bsp::TIP_HANDLE).pose);
  EXPECT_NEAR(tipped.stroke.a, to.stroke.a, 1e-12);
  EXPECT_NEAR(tipped.stroke.b, to.stroke.b, 1e-12);
  const bsp::Stroke sped = bsp::strokeAfterDrag(tipped, bsp::SPEED_HANDLE, named(target, bsp::SPEED_HANDLE).pose);
  EXPECT_NEAR(sped.speed, to.stroke.speed, 1e-12);
  EXPECT_NEAR(sped.phi, to.stroke.phi, 1e-12);
}

TEST(CueHandles, DragsStayWithinTheirRanges)
{
  const bsp::CueHandles h = handles();
  geometry_msgs::Pose pose;
  // The tip dragged far off the ball: the same direction on the face, at the largest offset.
  pose.position.x = h.ball.x();
  pose.position.y = h.ball.y();
  pose.position.z = h.radius + 5.0 * h.radius;
  const bsp::Stroke tipped = bsp::strokeAfterDrag(h, bsp::TIP_HANDLE, pose);
  EXPECT_NEAR(std::hypot(tipped.a, tipped.b), bsp::MAX_HANDLE_OFFSET, 1e-12);
  EXPECT_GT(tipped.b, 0.0);
  // The speed handle pushed through the ball, then pulled 10 m back.
  pose.position.z = h.radius;
  EXPECT_DOUBLE_EQ(bsp::strokeAfterDrag(h, bsp::SPEED_HANDLE, pose).speed, bsp::MIN_HANDLE_SPEED);
  const Eigen::Vector3d far = hitPoint(h) - 10.0 * cueDirection(h.stroke);
  pose.position.x = far.x();
  pose.position.y = far.y();
  pose.position.z = far.z();
  EXPECT_DOUBLE_EQ(bsp::strokeAfterDrag(h, bsp::SPEED_HANDLE, pose).speed, bsp::MAX_HANDLE_SPEED);
  // The cue turned to point up into the ball from below the cloth: elevation 0.
  const Eigen::Quaterniond upwards(Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()));
  pose.orientation.w = upwards.w();
  pose.orientation.x = upwards.x();
  pose.orientation.y = upwards.y();
  pose.orientation.z = upwards.z();
  EXPECT_DOUBLE_EQ(bsp::strokeAfterDrag(h, bsp::AIM_HANDLE, pose).theta, 0.0);
}

TEST(CueHandles, APoseOfNaNsOrAnUnknownMarkerLeavesTheStroke)
{
  const bsp::CueHandles h = handles();
  geometry_msgs::Pose pose;
  pose.position.x = std::numeric_limits<double>::quiet_NaN();
  pose.orientation.w = std::numeric_limits<double>::quiet_NaN();
  for (const char* marker : {bsp::AIM_HANDLE, bsp::TIP_HANDLE, bsp::SPEED_HANDLE, "other"})
  {
    const bsp::Stroke s = bsp::strokeAfterDrag(h, marker, pose);
    EXPECT_EQ(s.phi, h.stroke.phi) << marker;
    EXPECT_EQ(s.theta, h.stroke.theta) << marker;
    EXPECT_EQ(s.speed, h.stroke.speed) << marker;
    EXPECT_EQ(s.a, h.stroke.a) << marker;
    EXPECT_EQ(s.b, h.stroke.b) << marker;
  }
}
