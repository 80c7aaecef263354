#pragma once

#include <optional>

#include "billiard_shot_planner/motion/ball_motion.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The horizontal distance between the ball's centre and a cushion nose when they touch with the ball on the
/// cloth: R cos θ with sin θ = (h − R)/R, the nose being h above the cloth.
double cushionReach(const Table& table, double radius);

/// Unit normal of the cushion contact (from the nose towards the ball's centre) for cushion `rail` (0: −x, 1: +x,
/// 2: −y, 3: +y), with the ball's centre at `centre` (table frame) touching the nose.
Eigen::Vector3d cushionNormal(int rail, const Table& table, const Eigen::Vector3d& centre);

struct Crossing
{
  double time;  ///< from the segment start
  int index;    ///< the rail or the pocket
};

/// The first time in (0, horizon] at which the ball, moving along `segment`, touches a cushion nose while approaching
/// it, or, in the air, passes over a nose without touching it (then its bottom is above the nose).
std::optional<Crossing> firstCushionHit(const MotionSegment& segment, const Table& table, double radius,
                                        double horizon);

/// The first time in [0, horizon] at which the ball's centre enters a pocket's capture region.
std::optional<Crossing> firstPocketEntry(const MotionSegment& segment, const Table& table, double horizon);

}  // namespace detail
}  // namespace billiard_shot_planner
