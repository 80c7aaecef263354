#pragma once

#include <Eigen/Core>
#include <optional>

#include "billiard_shot_planner/scenarios/ball_collision.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Gap (m) within which two balls touch: the one gap of every impact (scenarios/ball_collision.hpp).
constexpr double BALL_TOUCHING_TOLERANCE = TOUCHING_GAP;

/// The gap |d(t)| − contact_distance (m) between two balls at time t of a phase in which both accelerate constantly:
/// d(t) = dp + dv t + ½ da t² is the position of one ball's centre relative to the other's, contact_distance the sum
/// of the radii. Negative when they overlap.
double ballGap(const Eigen::Vector3d& dp, const Eigen::Vector3d& dv, const Eigen::Vector3d& da, double contact_distance,
               double t);

/// The earliest time in [0, horizon] at which two balls with the relative motion d(t) of `ballGap` come into
/// contact while approaching, or nothing. The balls approach at t when their gap decreases right after t (the first
/// non-zero derivative of |d|² at t is negative, one within the round-off of its terms counting as zero); they touch
/// when the gap is at most BALL_TOUCHING_TOLERANCE.
/// Contact is the earliest of:
/// - a moment at which they touch and begin to approach: t = 0, or the end of a stretch in which they separated
///   (touching at the start and moving apart, or at rest, is no contact there);
/// - the moment at which the gap closes to 0 while they approach: exact, not shifted by the tolerance;
/// - a graze: the end of an approach (a closest approach, or the horizon) with the gap within (0, tolerance]. The
///   collision resolver then decides; a closest approach above the tolerance is a miss.
/// Overlapping inputs (gap < −tolerance) are the caller's error; they count as touching, so the answer is 0 if the
/// balls approach, else the moment they begin to approach. The gap never opens at the returned time. A horizon
/// beyond every root of |d|² − contact_distance² and of its derivatives (infinity included) ends there; a negative
/// or NaN horizon or non-finite motion gives nothing.
std::optional<double> earliestBallContact(const Eigen::Vector3d& dp, const Eigen::Vector3d& dv,
                                          const Eigen::Vector3d& da, double contact_distance, double horizon);

}  // namespace detail
}  // namespace billiard_shot_planner
