#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"

namespace billiard_shot_planner
{
// The strokes of the two pairwise simulators a user may compare with, and the way between them and this package's
// Stroke (docs/stroke_conventions.md). This package: φ and θ in radians, φ counter-clockwise from +x of the table
// frame (origin at the cloth's centre, x along the length towards the foot, z up), a > 0 right of centre as the
// player sees it (right english: the ball spins counter-clockwise seen from above), a and b in ball radii.

/// pooltool's Cue (pooltool/objects/cue/datatypes.py): V0 the cue's speed, m/s; phi and theta in degrees; a and b
/// the hit point in ball radii, a = +1 the ball's leftmost point as the player sees it. Its table frame has its
/// origin at a corner of the cloth, x across the width and y along the length from the head rail, z up.
struct PooltoolStroke
{
  double V0 = 0.0;     ///< m/s
  double phi = 0.0;    ///< deg, counter-clockwise from pooltool's +x (across the table)
  double theta = 0.0;  ///< deg
  double a = 0.0;      ///< ball radii, + left
  double b = 0.0;      ///< ball radii, + up
};

/// FastFiz's ShotParams(a, b, theta, phi, v) (FastFiz.h): a and b in millimetres, a > 0 right of centre; angles in
/// degrees; v the cue's speed, m/s. Its table frame has its origin at a corner of the cloth, x across the width and
/// y along the length with the head string at three quarters of it (the foot at y = 0), z up.
struct FastFizShot
{
  double a = 0.0;      ///< mm, + right
  double b = 0.0;      ///< mm, + up
  double theta = 0.0;  ///< deg
  double phi = 0.0;    ///< deg, counter-clockwise from FastFiz's +x (across the table)
  double v = 0.0;      ///< m/s
};

Stroke fromPooltool(const PooltoolStroke& stroke);
PooltoolStroke toPooltool(const Stroke& stroke);
/// `ball_radius`: m, the radius the millimetres are of.
Stroke fromFastFiz(const FastFizShot& shot, double ball_radius);
FastFizShot toFastFiz(const Stroke& stroke, double ball_radius);

/// A point of pooltool's table frame in this package's, and back: the frames differ by a quarter turn about z and the
/// origin (pooltool's head rail is at this package's −x end).
Eigen::Vector2d fromPooltoolPosition(const Eigen::Vector2d& point, const Table& table);
Eigen::Vector2d toPooltoolPosition(const Eigen::Vector2d& point, const Table& table);
/// A point of FastFiz's table frame in this package's, and back (FastFiz's head is at its +y end, this package's
/// −x end).
Eigen::Vector2d fromFastFizPosition(const Eigen::Vector2d& point, const Table& table);
Eigen::Vector2d toFastFizPosition(const Eigen::Vector2d& point, const Table& table);

}  // namespace billiard_shot_planner
