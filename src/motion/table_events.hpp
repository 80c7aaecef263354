#pragma once

#include <optional>
#include <vector>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Distance (m) within which the ball touches a cushion nose: the one gap of every impact
/// (scenarios/ball_collision.hpp), also the tolerance of a start position against the cushions.
constexpr double CONTACT_DISTANCE = TOUCHING_GAP;

/// Unit normal of the cushion contact (from the nose towards the ball's centre) for cushion `rail` (0: −x, 1: +x,
/// 2: −y, 3: +y), with the ball's centre at `centre` (table frame) touching the nose.
Eigen::Vector3d cushionNormal(int rail, const Table& table, const Eigen::Vector3d& centre);

/// The cushions (0: −x, 1: +x, 2: −y, 3: +y) whose nose a ball with its centre at `centre` touches, to
/// CONTACT_DISTANCE: its centre is R from the nose line, on the cloth or in the air.
std::vector<int> touchedCushions(const Eigen::Vector3d& centre, const Table& table, double radius);

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
  int rail;
  NoseContact contact;
};

/// The first time in [0, horizon] at which the ball, moving along `segment`, meets a cushion nose. A ball that
/// touches a nose at the start meets it there if it moves into it or is pressed into it; one that moves away
/// meets it only when it comes back. Contact is decided by geometry alone: in the air the ball can pass over a nose
/// only with its bottom above it.
std::optional<CushionCrossing> firstCushionHit(const MotionSegment& segment, const Table& table, double radius,
                                               double horizon);

struct Crossing
{
  double time;  ///< from the segment start
  int index;    ///< the pocket
};

/// The first time in [0, horizon] at which the ball's centre enters a pocket's capture region.
std::optional<Crossing> firstPocketEntry(const MotionSegment& segment, const Table& table, double horizon);

}  // namespace detail
}  // namespace billiard_shot_planner
