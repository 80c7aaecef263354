#include "prediction_message.hpp"

#include "geometry_conversions.hpp"

namespace billiard_shot_planner
{
namespace
{
static_assert(PathSample::AIRBORNE == static_cast<int>(MotionPhase::Airborne) &&
                  PathSample::SLIDING == static_cast<int>(MotionPhase::Sliding) &&
                  PathSample::ROLLING == static_cast<int>(MotionPhase::Rolling) &&
                  PathSample::SPINNING == static_cast<int>(MotionPhase::Spinning) &&
                  PathSample::STATIONARY == static_cast<int>(MotionPhase::Stationary),
              "PathSample.msg's phase constants must follow MotionPhase");

void fillStrike(ShotPrediction& m, const CueStrikeResult& strike, const Eigen::Vector3d& hit_point)
{
  m.ball_velocity = toVector3(strike.velocity);
  m.ball_angular_velocity = toVector3(strike.angular_velocity);
  m.hit_point = toPoint(hit_point);
  m.hit_normal = toVector3(strike.hit_normal);
  m.cue_direction = toVector3(strike.cue_direction);
  m.cue_speed_after = strike.cue_velocity;
  m.tip_velocity_after = toVector3(strike.tip_velocity);
  m.impulse_cue = toVector3(strike.impulse_cue);
  m.impulse_table = toVector3(strike.impulse_table);
  m.states = strike.states;
  m.miscue = strike.miscue;
  m.leaves_cloth = strike.leaves_cloth;
  m.converged = strike.impact.converged;
  const char* names[] = {"cue-ball", "ball-table"};
  for (const ContactEvent& e : strike.impact.events)
  {
    ImpactEvent event;
    event.type = toString(e.type);
    event.contact = names[e.contact];
    event.time = e.at.time;
    event.normal_impulses.assign(e.at.normal_impulses.data(),
                                 e.at.normal_impulses.data() + e.at.normal_impulses.size());
    m.contact_events.push_back(event);
  }
}

void fillTrajectory(ShotPrediction& m, const BallTrajectory& trajectory, double spacing)
{
  m.outcome = toString(trajectory.outcome);
  m.pocket = -1;
  m.cushion_hits = 0;
  for (const MotionEvent& e : trajectory.events)
  {
    TrajectoryEvent event;
    event.type = toString(e.type);
    event.time = e.time;
    event.position = toPoint(e.state.position);
    event.velocity = toVector3(e.state.velocity);
    event.angular_velocity = toVector3(e.state.angular_velocity);
    event.cushion = e.cushion;
    event.pocket = e.pocket;
    m.trajectory_events.push_back(event);
    m.cushion_hits += e.type == MotionEventType::CushionHit;
    if (e.type == MotionEventType::Pocketed)
      m.pocket = e.pocket;
  }
  m.final_position = toPoint(trajectory.finalState().position);
  m.duration = trajectory.duration();
  for (const TrajectorySample& s : trajectory.sample(spacing))
  {
    PathSample sample;
    sample.time = s.time;
    sample.position = toPoint(s.state.position);
    sample.phase = static_cast<uint8_t>(s.phase);  // the message constants follow MotionPhase's order
    m.trajectory.push_back(sample);
  }
}
}  // namespace

ShotPrediction toMessage(const ShotOutcome& outcome, const std::string& frame, double spacing)
{
  ShotPrediction m;
  m.header.frame_id = frame;
  fillStrike(m, outcome.strike, outcome.hit_point);
  fillTrajectory(m, outcome.trajectory, spacing);
  return m;
}

}  // namespace billiard_shot_planner
