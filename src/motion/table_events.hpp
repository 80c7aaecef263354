#pragma once

#include <array>
#include <optional>
#include <vector>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"
#include "motion_geometry.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Distance (m) within which the ball touches a cushion nose: the one gap of every impact
/// (scenarios/ball_collision.hpp), also the tolerance of a start position against the cushions.
constexpr double CONTACT_DISTANCE = TOUCHING_GAP;

/// Unit normal of the contact with `piece` (from its nose point towards the ball's centre), with the ball's centre at
/// `centre` (table frame) touching it.
Eigen::Vector3d cushionNormal(const NosePiece& piece, const Table& table, const Eigen::Vector3d& centre);

/// The pieces (indices of geometry.noses) whose nose a ball with its centre at `centre` touches, to CONTACT_DISTANCE:
/// its centre is R from the nose, on the cloth or in the air. Pieces that join where the ball touches give one
/// contact: the first of them.
std::vector<int> touchedNoses(const Eigen::Vector3d& centre, const MotionGeometry& geometry, const Table& table,
                              double radius);

/// How the ball meets a cushion nose.
enum class NoseContact
{
  Impact,   ///< it touches the nose approaching faster than REST_SPEED: an impact
  Pressed,  ///< it touches the nose without approaching while its motion presses it in: sustained contact begins
  Over,     ///< in the air, its centre passes over the nose line with its bottom above the nose: it leaves the table
};

struct CushionCrossing
{
  double time;  ///< from the segment start
  int piece;    ///< the index of geometry.noses
  NoseContact contact;
};

/// The first time in [0, horizon] at which the ball, moving along `segment`, meets a piece of a cushion's nose, where
/// the piece covers the ball's nearest nose point. A ball that touches a nose at the start meets it there if it moves
/// into it or is pressed into it; one that moves away meets it only when it comes back. Contact is decided by
/// geometry alone: in the air the ball can pass over a straight nose only with its bottom above it.
std::optional<CushionCrossing> firstCushionHit(const MotionSegment& segment, const MotionGeometry& geometry,
                                               const Table& table, double radius, double horizon);

struct Crossing
{
  double time;  ///< from the segment start
  int index;    ///< the drop region (the pocket)
};

/// The first time in [0, horizon] at which the ball's centre, moving along `segment`, comes within `radius` of
/// `centre` (table plane): 0 if it starts there, none if it does not come. Exact for the segment's quadratic path, by
/// the balls' contact search (earliestBallContact): its roots are isolated, not sampled, and a path that only grazes
/// the region's edge to within TOUCHING_GAP enters it at its closest approach.
std::optional<double> firstCircleEntry(const MotionSegment& segment, const Eigen::Vector2d& centre, double radius,
                                       double horizon);

/// The first time in [0, horizon] at which the ball's centre enters a drop region.
std::optional<Crossing> firstPocketEntry(const MotionSegment& segment, const MotionGeometry& geometry, double horizon);

}  // namespace detail
}  // namespace billiard_shot_planner
