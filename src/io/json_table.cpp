// The table_shot problem: the cue strike, then every ball on the table until all rest or leave it.
#include <algorithm>
#include <set>
#include <string>

#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/motion/table_strike.hpp"
#include "json_fields.hpp"
#include "json_table.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
std::string ballField(std::size_t i)
{
  return "balls[" + std::to_string(i) + "]";
}

Expected<TableBall> tableBall(const json& fields, std::size_t i, double radius)
{
  const std::string prefix = ballField(i);
  if (!fields.is_object())
    return invalidArgument(prefix, "must be an object {\"id\": \"…\", \"position\": [x, y]}");
  if (!fields.contains("id") || !fields.at("id").is_string())
    return invalidArgument(prefix + ".id", "is required: a string");
  auto state = ballOnCloth(fields, prefix, radius);
  if (!state)
    return state.error();
  return TableBall{fields.at("id").get<std::string>(), state.value()};
}

/// Samples at k·spacing up to the table's duration, the same instants for every ball, plus the ball's own events.
json samplesJson(const BallTrajectory& ball, double duration, double spacing)
{
  spacing = std::max(spacing, duration / static_cast<double>(BallTrajectory::MAX_SAMPLES));
  std::vector<double> times;
  for (std::size_t k = 0; static_cast<double>(k) * spacing < duration && k < BallTrajectory::MAX_SAMPLES; ++k)
    times.push_back(static_cast<double>(k) * spacing);
  for (const MotionEvent& event : ball.events)
    times.push_back(event.time);
  times.push_back(duration);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  json samples = json::array();
  for (double t : times)
    samples.push_back({{"t", t}, {"position", toVector3(ball.at(t).position)}, {"phase", toString(ball.phaseAt(t))}});
  return samples;
}

json ballJson(const std::string& id, const BallTrajectory& ball)
{
  json events = json::array();
  for (const MotionEvent& e : ball.events)
    events.push_back(eventJson(e));
  const auto pocketed = std::find_if(ball.events.begin(), ball.events.end(),
                                     [](const MotionEvent& e) { return e.type == MotionEventType::Pocketed; });
  return json{{"id", id},
              {"outcome", toString(ball.outcome)},
              {"pocket", pocketed == ball.events.end() ? json(nullptr) : json(pocketed->pocket)},
              {"final_position", toVector3(ball.finalState().position)},
              {"events", events}};
}

/// The id of the first ball the cue ball touches, or null.
json firstContactJson(const TableTrajectory& run, std::size_t cue)
{
  const std::string id = firstContact(run, cue);
  return id.empty() ? json(nullptr) : json(id);
}

Expected<bool> wantsSamples(const json& request)
{
  if (!request.contains("samples"))
    return false;
  if (!request.at("samples").is_boolean())
    return invalidArgument("samples", "must be true or false");
  return request.at("samples").get<bool>();
}
}  // namespace

Expected<std::vector<TableBall>> tableBalls(const json& request, double radius)
{
  if (!request.contains("balls") || !request.at("balls").is_array())
    return invalidArgument("balls", "is required: an array of {\"id\", \"position\": [x, y]}");
  std::vector<TableBall> balls;
  const json& list = request.at("balls");
  for (std::size_t i = 0; i < list.size() && i <= MAX_TABLE_BALLS; ++i)
  {
    auto ball = tableBall(list[i], i, radius);
    if (!ball)
      return ball.error();
    balls.push_back(ball.value());
  }
  return balls;
}

Expected<std::size_t> cueBallIndex(const json& request, const std::vector<TableBall>& balls)
{
  std::string id = "cue";
  if (request.contains("cue_ball"))
  {
    if (!request.at("cue_ball").is_string())
      return invalidArgument("cue_ball", "must be the id of a ball");
    id = request.at("cue_ball").get<std::string>();
  }
  const auto found = std::find_if(balls.begin(), balls.end(), [&](const TableBall& b) { return b.id == id; });
  if (found == balls.end())
    return invalidArgument("cue_ball", "no ball has the id \"" + id + "\"");
  return static_cast<std::size_t>(found - balls.begin());
}

json tableJson(const TableTrajectory& run, std::size_t cue, const MotionSetup& setup, bool samples)
{
  json balls = json::array(), pocketed = json::array(), collisions = json::array();
  for (std::size_t i = 0; i < run.balls.size(); ++i)
  {
    json ball = ballJson(run.ids[i], run.balls[i]);
    if (samples)
      ball["samples"] = samplesJson(run.balls[i], run.duration(), setup.spacing);
    for (const MotionEvent& e : run.balls[i].events)
      if (e.type == MotionEventType::Pocketed)
        pocketed.push_back({{"id", run.ids[i]}, {"pocket", e.pocket}, {"t", e.time}});
    balls.push_back(ball);
  }
  for (const BallImpactRecord& impact : run.ball_impacts)
  {
    json ids = json::array();
    for (int b : impact.balls)
      ids.push_back(run.ids[static_cast<std::size_t>(b)]);
    collisions.push_back({{"t", impact.time}, {"balls", ids}});
  }
  return json{{"balls", balls},
              {"first_contact", firstContactJson(run, cue)},
              {"pocketed", pocketed},
              {"collisions", collisions},
              {"duration", run.duration()}};
}

Expected<json> solveTableShot(const json& request, const SolverOptions& options)
{
  // Every field is read before the strike is solved: bad input costs nothing.
  auto setup = strikeSetup(request, options);
  if (!setup)
    return setup.error();
  const CueStrike& s = setup.value().strike;
  auto balls = tableBalls(request, s.ball_radius);
  if (!balls)
    return balls.error();
  auto cue = cueBallIndex(request, balls.value());
  if (!cue)
    return cue.error();
  auto contact = ballContactFromJson(request);
  if (!contact)
    return contact.error();
  auto samples = wantsSamples(request);
  if (!samples)
    return samples.error();
  const MotionSetup& m = setup.value().motion;
  auto solved = strikeOnTable(s, balls.value(), cue.value(), m.table, contact.value(), options);
  if (!solved)
    return solved.error();
  const std::vector<TableBall> start = ballsAfterStrike(balls.value(), cue.value(), solved.value());
  auto run = simulateTable(start, m.ball, m.table, m.parameters, contact.value());
  if (!run)
    return run.error();
  recordStrike(run.value(), cue.value(), solved.value());
  json answer = tableJson(run.value(), cue.value(), m, samples.value());
  answer["strike"] = cueStrikeJson(solved.value(), run.value().ids);
  return answer;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
