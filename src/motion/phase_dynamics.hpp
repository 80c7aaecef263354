#pragma once

#include <limits>

#include "billiard_shot_planner/motion/ball_motion.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Speeds below this (m/s, or rad/s × m) are zero: the phase has ended.
constexpr double REST_SPEED = 1e-9;
constexpr double NEVER = std::numeric_limits<double>::infinity();

/// Which phase a state is in (docs/impact_model.md, Motion on the table): off the cloth, slipping, rolling,
/// spinning or at rest.
MotionPhase classify(const BallState& state, double radius);

/// Contact slip velocity on the cloth, u = v + R ẑ × ω (its xy part).
Eigen::Vector2d contactSlip(const BallState& state, double radius);

/// Deceleration (m/s²) of a ball rolling freely on the cloth.
double rollingDeceleration(const MotionParameters& p);
/// Angular deceleration (rad/s²) of the spin about z on the cloth.
double spinDeceleration(const BallProperties& ball, const MotionParameters& p);

/// The closed-form motion of one phase: constant accelerations, and when the phase ends by itself.
struct PhaseMotion
{
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();
  double end = NEVER;                                 ///< duration until the phase ends by itself
  MotionEventType end_event = MotionEventType::Rest;  ///< what happens then
};

PhaseMotion phaseMotion(MotionPhase phase, const BallState& state, const BallProperties& ball,
                        const MotionParameters& p);

/// The state at the natural end of a phase, with the quantity that reached zero set exactly to zero.
BallState snapPhaseEnd(MotionEventType event, BallState state, double radius);

}  // namespace detail
}  // namespace billiard_shot_planner
