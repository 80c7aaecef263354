#pragma once

// One ball's motion on the table, event by event: closed-form phases, and the events it meets on its own (a phase
// ending, a landing, a cushion, a pocket, the time limit). The table's simulation runs one mover per ball and
// interrupts a mover where the ball meets another ball.
#include <chrono>
#include <limits>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "phase_dynamics.hpp"
#include "table_events.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The wall-clock deadline shared by every impact of one simulation (SolverOptions::max_seconds bounds the whole).
using Deadline = std::chrono::steady_clock::time_point;

Deadline deadlineAfter(double seconds);

/// Checks what every simulation on a table needs: the ball's mass and radius, the motion parameters, the table and
/// its cushions' height against the ball.
Status checkMotionSetting(const BallProperties& ball, const Table& table, const MotionParameters& parameters);

/// Checks a ball's start: finite, plausible speeds, on the cloth, clear of the cushions (`geometry`'s noses) and
/// outside the drop regions. The error names the field ("position", "v", "omega") after `prefix` ("balls[3].").
Status checkStart(const BallState& start, const BallProperties& ball, const Table& table,
                  const MotionGeometry& geometry, const std::string& prefix = "");

class BallMover
{
public:
  enum class Status
  {
    Moving,   ///< on a segment that ends at nextEventTime()
    Resting,  ///< at rest on the cloth: another ball may set it moving again
    Ended,    ///< pocketed, off the table, pressed against a cushion or at the time limit
  };

  BallMover(const BallProperties& ball, const Table& table, const MotionGeometry& geometry,
            const MotionParameters& parameters, const Deadline& deadline);

  /// The Start event at t = 0 and the first segment.
  void begin(BallState state);
  Status status() const { return status_; }
  /// Absolute time of the current segment's own end; +∞ when the ball rests or has ended.
  double nextEventTime() const;
  /// The current segment (a resting ball's: stationary from its rest time, without end).
  const MotionSegment& segment() const { return segment_; }
  /// Ends the current segment at its own end, handles its event and plans the next segment.
  Expected<bool> runOwnEvent();
  /// Ends the current segment at time t < nextEventTime() where an impact with other balls gives the ball the
  /// state `after`, records it as a BallCollision event with `other` (the index of a ball it met) and plans on.
  void interrupt(double t, const BallState& after, int other);
  /// Ends the current segment at time t and goes on along `next` (from t, accelerations given: a step of a linked
  /// pair) until the step's end or an own event of the ball (cushion, pocket, time limit). No event is recorded.
  void follow(double t, const MotionSegment& next);
  /// Records the phase change `event` at time t (a linked ball's slip or roll ending) with the state after it; the
  /// next follow() or release() goes on from there.
  void recordPhaseChange(double t, MotionEventType event, const BallState& after)
  {
    trajectory_.events.push_back({event, t, after});
  }
  /// Ends the current segment at time t and plans the ball's own motion from `state` (a linked pair let go).
  void release(double t, const BallState& state);
  /// Moves the trajectory out; the mover is done.
  BallTrajectory takeTrajectory() { return std::move(trajectory_); }
  const BallTrajectory& trajectory() const { return trajectory_; }
  /// Counts changes of the current segment: a cache of contact times is valid while both balls' counts stay.
  unsigned version() const { return version_; }

private:
  /// Where one phase ends: by itself, at a cushion, in a pocket or at the time limit.
  struct SegmentEnd
  {
    double duration = std::numeric_limits<double>::infinity();
    MotionEventType event = MotionEventType::Rest;
    int piece = -1;  ///< the nose piece it meets (geometry_.noses)
    int pocket = -1;
    NoseContact contact = NoseContact::Impact;
  };

  void plan(const BallState& state, double t);
  /// Ends the current segment at t (a resting ball's too, so that its path holds still up to t).
  void closeSegment(double t);
  /// Ends the current segment at t; one that would have no length is dropped.
  void continueAt(double t);
  SegmentEnd segmentEnd(const MotionSegment& segment, const PhaseMotion& motion, double t) const;
  Expected<bool> hitCushion(int piece, NoseContact contact, BallState& state, double t);
  Expected<bool> land(BallState& state, double t);
  Expected<SolverOptions> impactOptions() const;
  bool pressedAgainst(int piece, bool on_cloth, double approach) const;
  void end(MotionEventType event, MotionOutcome outcome, double t, const BallState& state);

  const BallProperties& ball_;
  const Table& table_;
  const MotionGeometry& geometry_;
  const MotionParameters& p_;
  const Deadline& deadline_;
  BallTrajectory trajectory_;
  MotionSegment segment_;
  SegmentEnd end_;
  Status status_ = Status::Resting;
  unsigned version_ = 0;
  struct CushionHitRecord
  {
    int piece = -1;
    bool on_cloth = false;
    double rebound_speed = 0.0;  ///< m/s away from the cushion: horizontally on the cloth, along the normal in the air
  } last_hit_;
};

}  // namespace detail
}  // namespace billiard_shot_planner
