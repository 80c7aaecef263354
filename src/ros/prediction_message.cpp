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
  for (const ContactEvent& e : strike.impact.events)
  {
    ImpactEvent event;
    event.type = toString(e.type);
    event.contact = e.contact < strike.contacts.size() ? strike.contacts[e.contact].name : "";
    event.time = e.at.time;
    event.normal_impulses.assign(e.at.normal_impulses.data(),
                                 e.at.normal_impulses.data() + e.at.normal_impulses.size());
    m.contact_events.push_back(event);
  }
  for (const StrikeContact& c : strike.contacts)
  {
    StrikeImpulse contact;
    contact.name = c.name;
    contact.impulse = toVector3(c.impulse);
    m.strike_contacts.push_back(contact);
  }
}

void fillStruckBalls(ShotPrediction& m, const CueStrikeResult& strike, const std::vector<std::string>& ids)
{
  for (const StruckBall& b : strike.other_balls)
  {
    BallAfterStrike ball;
    ball.id = b.ball < ids.size() ? ids[b.ball] : "";
    ball.velocity = toVector3(b.velocity);
    ball.angular_velocity = toVector3(b.angular_velocity);
    m.struck_balls.push_back(ball);
  }
}

TrajectoryEvent eventMessage(const MotionEvent& e, const std::vector<std::string>& ids)
{
  TrajectoryEvent event;
  event.type = toString(e.type);
  event.time = e.time;
  event.position = toPoint(e.state.position);
  event.velocity = toVector3(e.state.velocity);
  event.angular_velocity = toVector3(e.state.angular_velocity);
  event.cushion = e.cushion;
  event.pocket = e.pocket;
  if (e.ball >= 0 && static_cast<std::size_t>(e.ball) < ids.size())
    event.ball = ids[static_cast<std::size_t>(e.ball)];
  return event;
}

std::vector<PathSample> pathMessage(const BallTrajectory& trajectory, double spacing)
{
  std::vector<PathSample> path;
  for (const TrajectorySample& s : trajectory.sample(spacing))
  {
    PathSample sample;
    sample.time = s.time;
    sample.position = toPoint(s.state.position);
    sample.phase = static_cast<uint8_t>(s.phase);  // the message constants follow MotionPhase's order
    path.push_back(sample);
  }
  return path;
}

void fillTrajectory(ShotPrediction& m, const BallTrajectory& trajectory, const std::vector<std::string>& ids,
                    double spacing)
{
  m.outcome = toString(trajectory.outcome);
  m.pocket = trajectory.pocket();
  m.cushion_hits = 0;
  for (const MotionEvent& e : trajectory.events)
  {
    m.trajectory_events.push_back(eventMessage(e, ids));
    m.cushion_hits += e.type == MotionEventType::CushionHit;
  }
  m.final_position = toPoint(trajectory.finalState().position);
  m.duration = trajectory.duration();
  m.trajectory = pathMessage(trajectory, spacing);
}

void fillTable(ShotPrediction& m, const TableTrajectory& table, double spacing)
{
  for (std::size_t i = 0; i < table.balls.size(); ++i)
  {
    BallPrediction ball;
    ball.id = table.ids[i];
    ball.outcome = toString(table.balls[i].outcome);
    ball.pocket = table.balls[i].pocket();
    ball.final_position = toPoint(table.balls[i].finalState().position);
    for (const MotionEvent& e : table.balls[i].events)
      ball.events.push_back(eventMessage(e, table.ids));
    ball.path = pathMessage(table.balls[i], spacing);
    m.balls.push_back(ball);
  }
  m.first_contact = firstContact(table);
}
}  // namespace

ShotPrediction toMessage(const ShotOutcome& outcome, const std::string& frame, double spacing)
{
  ShotPrediction m;
  m.header.frame_id = frame;
  fillStrike(m, outcome.strike, outcome.hit_point);
  fillStruckBalls(m, outcome.strike, outcome.table.ids);
  fillTrajectory(m, outcome.trajectory, outcome.table.ids, spacing);
  fillTable(m, outcome.table, spacing);
  return m;
}

}  // namespace billiard_shot_planner
