#include "billiard_shot_planner/motion/ball_trajectory.hpp"

#include <algorithm>

namespace billiard_shot_planner
{
const char* toString(MotionPhase phase)
{
  switch (phase)
  {
    case MotionPhase::Airborne:
      return "airborne";
    case MotionPhase::Sliding:
      return "sliding";
    case MotionPhase::Rolling:
      return "rolling";
    case MotionPhase::Spinning:
      return "spinning";
    case MotionPhase::Stationary:
      return "stationary";
  }
  return "unknown";
}

const char* toString(MotionEventType type)
{
  switch (type)
  {
    case MotionEventType::Start:
      return "start";
    case MotionEventType::Landing:
      return "landing";
    case MotionEventType::SlideToRoll:
      return "slide_to_roll";
    case MotionEventType::RollToSpin:
      return "roll_to_spin";
    case MotionEventType::SpinStop:
      return "spin_stop";
    case MotionEventType::CushionHit:
      return "cushion_hit";
    case MotionEventType::CushionContact:
      return "cushion_contact";
    case MotionEventType::Pocketed:
      return "pocketed";
    case MotionEventType::BallCollision:
      return "ball_collision";
    case MotionEventType::Rest:
      return "rest";
    case MotionEventType::TimeLimit:
      return "time_limit";
  }
  return "unknown";
}

const char* toString(MotionOutcome outcome)
{
  switch (outcome)
  {
    case MotionOutcome::Rest:
      return "rest";
    case MotionOutcome::Pocketed:
      return "pocketed";
    case MotionOutcome::OffTable:
      return "off_table";
    case MotionOutcome::AgainstCushion:
      return "against_cushion";
    case MotionOutcome::TimeLimit:
      return "time_limit";
  }
  return "unknown";
}

BallState MotionSegment::at(double t) const
{
  const double tau = t - start_time;
  BallState state;
  state.position = start.position + start.velocity * tau + 0.5 * acceleration * tau * tau;
  state.velocity = start.velocity + acceleration * tau;
  state.angular_velocity = start.angular_velocity + angular_acceleration * tau;
  return state;
}

namespace
{
const MotionSegment* segmentAt(const std::vector<MotionSegment>& segments, double t)
{
  if (segments.empty())
    return nullptr;
  auto it = std::upper_bound(segments.begin(), segments.end(), t,
                             [](double time, const MotionSegment& s) { return time < s.end_time; });
  return it == segments.end() ? &segments.back() : &*it;
}
}  // namespace

BallState BallTrajectory::at(double t) const
{
  const MotionSegment* segment = segmentAt(segments, t);
  if (!segment)
    return events.empty() ? BallState{} : events.front().state;
  if (t >= duration())
    return finalState();
  return segment->at(std::clamp(t, segment->start_time, segment->end_time));
}

const std::string& BallTrajectory::pocket() const
{
  static const std::string none;
  return outcome == MotionOutcome::Pocketed && !events.empty() ? events.back().pocket : none;
}

MotionPhase BallTrajectory::phaseAt(double t) const
{
  const MotionSegment* segment = segmentAt(segments, t);
  return segment ? segment->phase : MotionPhase::Stationary;
}

std::vector<TrajectorySample> BallTrajectory::sample(double spacing) const
{
  spacing = std::max(spacing, duration() / static_cast<double>(MAX_SAMPLES));
  std::vector<double> times;
  for (std::size_t k = 0; static_cast<double>(k) * spacing < duration() && k < MAX_SAMPLES; ++k)
    times.push_back(static_cast<double>(k) * spacing);
  for (const MotionEvent& event : events)
    times.push_back(event.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<TrajectorySample> samples;
  samples.reserve(times.size());
  for (double t : times)
    samples.push_back({t, at(t), phaseAt(t)});
  return samples;
}

}  // namespace billiard_shot_planner
