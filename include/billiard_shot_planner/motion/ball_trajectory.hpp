#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace billiard_shot_planner
{
/// Position of the ball's centre (table frame; z = radius when on the cloth), velocity and angular velocity.
struct BallState
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
};

enum class MotionPhase
{
  Airborne,    ///< off the cloth: a parabola under gravity
  Sliding,     ///< on the cloth with contact slip: constant friction against the slip (the massé curve)
  Rolling,     ///< on the cloth without slip: decelerates with rolling resistance
  Spinning,    ///< at rest in the plane, still turning about z
  Stationary,  ///< at rest
};

enum class MotionEventType
{
  Start,
  Landing,      ///< touches the cloth after a flight (a compliant ball–cloth impact)
  SlideToRoll,  ///< contact slip reaches zero
  RollToSpin,   ///< planar velocity reaches zero
  SpinStop,     ///< spin about z reaches zero
  CushionHit,   ///< a multiple impact with the cushion nose and the cloth
  /// The ball comes back to the cushion it last left, both times slower than 1e-6 m/s: its spin presses it against
  /// the cushion (sustained contact, not modelled; the path ends)
  CushionContact,
  Pocketed,       ///< the centre enters a pocket's capture region or drop region
  BallCollision,  ///< a multiple impact with the other balls that touch it, the cloth and any cushion they touch
  Rest,           ///< everything has stopped
  TimeLimit,      ///< the trajectory was cut at MotionParameters::max_time or max_events
};

enum class MotionOutcome
{
  Rest,
  Pocketed,
  OffTable,        ///< jumped over a cushion
  AgainstCushion,  ///< pressed against a cushion, where sustained contact would begin (not modelled)
  TimeLimit,
};

const char* toString(MotionPhase phase);
const char* toString(MotionEventType type);
const char* toString(MotionOutcome outcome);

/// One phase of motion between two events, in closed form: constant linear and angular acceleration, so
/// position(τ) = p0 + v0 τ + ½ a τ², velocity(τ) = v0 + a τ, angular_velocity(τ) = ω0 + α τ, τ = t − start_time.
struct MotionSegment
{
  MotionPhase phase = MotionPhase::Stationary;
  double start_time = 0.0;
  double end_time = 0.0;
  BallState start;
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();

  BallState at(double t) const;
};

struct MotionEvent
{
  MotionEventType type;
  double time;
  BallState state;  ///< after the event (after the impact for landings and cushion hits)
  /// Cushion hits and contacts: the cushion segment's id ("rail.top", "pocket.top_right.jaw.right.point").
  std::string cushion{};
  std::string pocket{};  ///< pocketed: the pocket's id ("top_right")
  int ball = -1;         ///< index of a ball it met, in the simulation's list (ball collisions)
};

struct TrajectorySample
{
  double time;
  BallState state;
  MotionPhase phase;
};

/// The predicted path of the ball after the shot: segments in closed form, the events between them, and how it
/// ended.
struct BallTrajectory
{
  std::vector<MotionSegment> segments;
  std::vector<MotionEvent> events;
  MotionOutcome outcome = MotionOutcome::Rest;

  double duration() const { return segments.empty() ? 0.0 : segments.back().end_time; }
  const BallState& finalState() const { return events.back().state; }
  /// The id of the pocket the ball dropped into, or empty.
  const std::string& pocket() const;
  /// State at time t (clamped to [0, duration]).
  BallState at(double t) const;
  MotionPhase phaseAt(double t) const;
  /// Samples every `spacing` seconds, plus every event time, in order. At most MAX_SAMPLES are spaced: on a path
  /// longer than MAX_SAMPLES · spacing the spacing widens to duration / MAX_SAMPLES, so that an answer stays
  /// bounded (a 600 s path at 1 ms would be 600 000 samples).
  std::vector<TrajectorySample> sample(double spacing) const;
  static constexpr std::size_t MAX_SAMPLES = 20000;
};

}  // namespace billiard_shot_planner
