#pragma once

// Two balls in sustained contact on the cloth (docs/engine.md, Sustained contact between balls): the limit of a
// Zeno sequence of ever smaller collisions, moved as one linked pair by the contact force that keeps their gap
// closed, in steps of constant acceleration.
#include <array>

#include "billiard_shot_planner/motion/ball_motion.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Distance (m) the rest of a collision sequence may still open between two pressed balls for the sequence to be
/// taken at its limit: a rebound at speed v against a relative acceleration p pressing the balls together opens at
/// most v²/(2p). A micrometre: far below anything a predicted path resolves.
constexpr double LINK_EXCURSION = 1e-6;

/// How two balls meet at an instant: the unit normal from a to b (horizontal), the approach speed along it and the
/// relative acceleration of their free motions that presses them together (centripetal part of their tangential
/// relative motion included; negative when their own motions part them).
struct PairPress
{
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double approach = 0.0;
  double press = 0.0;
};

PairPress pairPress(const MotionSegment& a, const MotionSegment& b, double t);

/// Whether a meeting is the limit of a Zeno sequence: the balls press together and what remains of the sequence
/// keeps them within LINK_EXCURSION of each other.
bool isSequenceLimit(const PairPress& press);

/// One step of a linked pair: both balls' segments from the step's start (constant accelerations), its duration,
/// and for each ball the phase that ends with the step (SlideToRoll, RollToSpin, SpinStop) or Rest for none. The
/// segments start on the cloth (a hop within LINK_EXCURSION dropped) and touching (a gap within the touching
/// tolerance closed, half by each ball along the line of centres).
/// `released`: the contact force would not press (or a ball is off the cloth); the balls move apart on their own.
struct LinkStep
{
  bool released = true;
  double duration = 0.0;
  double force = 0.0;  ///< N, the contact force through both centres
  std::array<MotionSegment, 2> segments;
  std::array<MotionEventType, 2> ends{MotionEventType::Rest, MotionEventType::Rest};
};

LinkStep linkStep(const BallState& a, const BallState& b, double t, const BallProperties& ball,
                  const MotionParameters& p);

/// The state at the end of a linked step's phase: a slip ended by the friction impulse that takes what is left of
/// it to zero (it only dissipates), a roll stopped, a spin stopped.
BallState endLinkedPhase(MotionEventType event, BallState state, double radius);

}  // namespace detail
}  // namespace billiard_shot_planner
