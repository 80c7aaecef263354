#include "phase_dynamics.hpp"

#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
double rollingDeceleration(const MotionParameters& p)
{
  const double scale = p.rolling_model == RollingModel::Paper ? 5.0 / 7.0 : 1.0;
  return scale * p.rolling_friction * p.gravity;
}

double spinDeceleration(const BallProperties& ball, const MotionParameters& p)
{
  return 5.0 * p.spinning_friction * p.gravity / (2.0 * ball.radius);
}

namespace
{
/// Spin about z decays linearly on the cloth (docs/impact_model.md, Motion on the table); returns its angular
/// deceleration and stop time.
void addSpinDecay(PhaseMotion& motion, const BallState& state, const BallProperties& ball, const MotionParameters& p)
{
  const double w_z = state.angular_velocity.z();
  if (std::abs(w_z) <= REST_SPEED / ball.radius)
    return;
  const double rate = spinDeceleration(ball, p);
  motion.angular_acceleration.z() = -std::copysign(rate, w_z);
  const double stop = std::abs(w_z) / rate;
  if (stop < motion.end)
  {
    motion.end = stop;
    motion.end_event = MotionEventType::SpinStop;
  }
}

/// Time until z(τ) = R on the way down: z0 + v_z τ − ½gτ² = R.
double flightTime(const BallState& state, const BallProperties& ball, double gravity)
{
  const double v_z = state.velocity.z();
  const double height = std::max(state.position.z() - ball.radius, 0.0);
  return (v_z + std::sqrt(v_z * v_z + 2.0 * gravity * height)) / gravity;
}
}  // namespace

Eigen::Vector2d contactSlip(const BallState& state, double radius)
{
  const Eigen::Vector3d& v = state.velocity;
  const Eigen::Vector3d& w = state.angular_velocity;
  return {v.x() - radius * w.y(), v.y() + radius * w.x()};
}

MotionPhase classify(const BallState& state, double radius)
{
  const bool off_cloth = state.position.z() > radius * (1.0 + 1e-12) || state.velocity.z() > 0.0;
  if (off_cloth)
    return MotionPhase::Airborne;
  if (contactSlip(state, radius).norm() > REST_SPEED)
    return MotionPhase::Sliding;
  if (state.velocity.head<2>().norm() > REST_SPEED)
    return MotionPhase::Rolling;
  if (std::abs(state.angular_velocity.z()) * radius > REST_SPEED)
    return MotionPhase::Spinning;
  return MotionPhase::Stationary;
}

PhaseMotion phaseMotion(MotionPhase phase, const BallState& state, const BallProperties& ball,
                        const MotionParameters& p)
{
  PhaseMotion motion;
  switch (phase)
  {
    case MotionPhase::Airborne:
      motion.acceleration.z() = -p.gravity;
      motion.end = flightTime(state, ball, p.gravity);
      motion.end_event = MotionEventType::Landing;
      return motion;
    case MotionPhase::Sliding:
    {
      // Friction μ_s m g against the slip û; the slip shrinks at (7/2) μ_s g (docs/impact_model.md, Motion on the
      // table).
      const Eigen::Vector2d u = contactSlip(state, ball.radius);
      const Eigen::Vector2d slip = u.normalized();
      const double friction = p.sliding_friction * p.gravity;
      motion.acceleration.head<2>() = -friction * slip;
      const double spin_up = 5.0 * friction / (2.0 * ball.radius);
      motion.angular_acceleration.head<2>() = spin_up * Eigen::Vector2d(-slip.y(), slip.x());  // (5μg/2R) ẑ × û
      motion.end = 2.0 * u.norm() / (7.0 * friction);
      motion.end_event = MotionEventType::SlideToRoll;
      break;
    }
    case MotionPhase::Rolling:
    {
      const Eigen::Vector2d v = state.velocity.head<2>();
      const double deceleration = rollingDeceleration(p);
      motion.acceleration.head<2>() = -deceleration * v.normalized();
      // Keeps ω_xy = ẑ × v / R.
      motion.angular_acceleration.head<2>() =
          Eigen::Vector2d(-motion.acceleration.y(), motion.acceleration.x()) / ball.radius;
      motion.end = v.norm() / deceleration;
      motion.end_event = MotionEventType::RollToSpin;
      break;
    }
    case MotionPhase::Spinning:
    case MotionPhase::Stationary:
      break;
  }
  addSpinDecay(motion, state, ball, p);
  return motion;
}

BallState snapPhaseEnd(MotionEventType event, BallState state, double radius)
{
  switch (event)
  {
    case MotionEventType::SlideToRoll:
      state.angular_velocity.x() = -state.velocity.y() / radius;
      state.angular_velocity.y() = state.velocity.x() / radius;
      break;
    case MotionEventType::RollToSpin:
      state.velocity.setZero();
      state.angular_velocity.head<2>().setZero();
      break;
    case MotionEventType::SpinStop:
      state.angular_velocity.z() = 0.0;
      break;
    default:
      break;
  }
  return state;
}

}  // namespace detail
}  // namespace billiard_shot_planner
