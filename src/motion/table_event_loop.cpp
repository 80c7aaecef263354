#include "table_event_loop.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>

#include "ball_contact_time.hpp"
#include "ball_mover.hpp"
#include "billiard_shot_planner/core/validation.hpp"
#include "linked_pair.hpp"
#include "table_collisions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
constexpr double NEVER = std::numeric_limits<double>::infinity();
/// Steps of one link before it is let go: a linked pair rolls for seconds in steps of milliseconds (a few thousand);
/// a pair whose steps shrink without end goes on as two balls, whose meetings count as events (max_events).
constexpr int MAX_LINK_STEPS = 100000;

/// The event loop over all balls. Pair contact times are cached and recomputed only when one of the two balls'
/// segments has changed. Two balls pressed together are one linked pair (linked_pair.hpp), moved in steps.
class TableSimulation
{
public:
  TableSimulation(const std::vector<TableBall>& balls, const BallProperties& ball, const Table& table,
                  const MotionGeometry& geometry, const MotionParameters& p, const BallContactSettings& contact)
      : ball_(ball),
        table_(table),
        geometry_(geometry),
        p_(p),
        contact_(contact),
        deadline_(deadlineAfter(p.impact.max_seconds))
  {
    movers_.reserve(balls.size());
    for (const TableBall& b : balls)
    {
      result_.ids.push_back(b.id);
      movers_.emplace_back(ball_, table_, geometry_, p_, deadline_);
    }
    for (std::size_t i = 0; i < balls.size(); ++i)
      movers_[i].begin(balls[i].state);
    pairs_.assign(balls.size() * balls.size(), PairContact{});
    partner_.assign(balls.size(), -1);
  }

  Expected<TableTrajectory> run()
  {
    while (true)
    {
      const auto [own_time, mover] = earliestOwnEvent();
      const auto [link_time, link] = earliestLinkEnd();
      const double horizon = std::min(own_time, link_time);
      const auto [contact_time, pair] = earliestContact(horizon);
      if (contact_time < horizon)
      {
        if (Status status = collide(contact_time, pair.first, pair.second); !status)
          return status.error();
        continue;
      }
      if (link_time < own_time)
      {
        // A link's steps record no events, so max_events does not bound them: the wall clock does.
        if (std::chrono::steady_clock::now() >= deadline_)
          return Error{ErrorKind::TimeLimitExceeded, "",
                       "the balls did not come to rest within " + formatNumber(p_.impact.max_seconds) +
                           " s of computation (a linked pair's steps)"};
        stepLink(link, link_time);
        continue;
      }
      if (mover < 0)
        break;
      auto ended = movers_[mover].runOwnEvent();
      if (!ended)
        return ended.error();
      if (partner_[mover] >= 0)
        unlink(mover, own_time);
    }
    for (BallMover& m : movers_)
      result_.balls.push_back(m.takeTrajectory());
    return std::move(result_);
  }

private:
  struct PairContact
  {
    unsigned version_i = 0, version_j = 0;  ///< the segments' versions it was computed for (0: never)
    double time = NEVER;
  };

  /// A linked pair's current step: its balls (a < b), its end, and the phase each ball ends it with.
  struct Link
  {
    int a = -1, b = -1;
    double end = NEVER;
    int steps = 0;
    std::array<MotionEventType, 2> ends{MotionEventType::Rest, MotionEventType::Rest};
  };

  std::pair<double, int> earliestLinkEnd() const
  {
    double earliest = NEVER;
    int link = -1;
    for (std::size_t k = 0; k < links_.size(); ++k)
      if (links_[k].end < earliest)
      {
        earliest = links_[k].end;
        link = static_cast<int>(k);
      }
    return {earliest, link};
  }

  /// Ends link `k`'s step at t: the phases that end there, then the next step or the release.
  void stepLink(int k, double t)
  {
    Link& link = links_[k];
    std::array<BallState, 2> states{movers_[link.a].segment().at(t), movers_[link.b].segment().at(t)};
    const std::array<int, 2> balls{link.a, link.b};
    for (int m = 0; m < 2; ++m)
      if (link.ends[m] != MotionEventType::Rest)
      {
        states[m] = endLinkedPhase(link.ends[m], states[m], ball_.radius);
        movers_[balls[m]].recordPhaseChange(t, link.ends[m], states[m]);
      }
    if (++link.steps > MAX_LINK_STEPS || !advanceLink(link, t, states))
      removeLink(k, t, states);
  }

  /// Plans the pair's next step from `states` at t; false when the balls no longer press together.
  bool advanceLink(Link& link, double t, const std::array<BallState, 2>& states)
  {
    const LinkStep step = linkStep(states[0], states[1], t, ball_, p_);
    if (step.released)
      return false;
    movers_[link.a].follow(t, step.segments[0]);
    movers_[link.b].follow(t, step.segments[1]);
    link.end = t + step.duration;
    link.ends = step.ends;
    return movers_[link.a].status() == BallMover::Status::Moving &&
           movers_[link.b].status() == BallMover::Status::Moving;
  }

  /// Lets a link go at t: each ball that still moves goes on its own from its state there.
  void removeLink(int k, double t, const std::array<BallState, 2>& states)
  {
    const Link link = dissolve(k);
    goOn(link.a, t, states[0]);
    goOn(link.b, t, states[1]);
  }

  /// Removes link k: its balls are no one's partners. Returns it.
  Link dissolve(int k)
  {
    const Link link = links_[k];
    links_.erase(links_.begin() + k);
    partner_[link.a] = partner_[link.b] = -1;
    return link;
  }

  /// Ball m, unless it has ended, goes on alone from `state` at t.
  void goOn(int m, double t, const BallState& state)
  {
    if (movers_[m].status() != BallMover::Status::Ended)
      movers_[m].release(t, state);
  }

  void goOn(int m, double t) { goOn(m, t, movers_[m].segment().at(t)); }

  int linkOf(int ball) const
  {
    for (std::size_t k = 0; k < links_.size(); ++k)
      if (links_[k].a == ball || links_[k].b == ball)
        return static_cast<int>(k);
    return -1;
  }

  /// Ball `ball` has left its link at t by an event of its own (its mover already went on): its partner goes on
  /// alone.
  void unlink(int ball, double t)
  {
    const Link link = dissolve(linkOf(ball));
    goOn(link.a == ball ? link.b : link.a, t);
  }

  /// Links balls i and j at t where their motion after the impact presses them together.
  void startLink(double t, int i, int j)
  {
    Link link{std::min(i, j), std::max(i, j)};
    const std::array<BallState, 2> states{movers_[link.a].segment().at(t), movers_[link.b].segment().at(t)};
    if (movers_[link.a].status() != BallMover::Status::Moving || movers_[link.b].status() != BallMover::Status::Moving)
      return;
    if (!advanceLink(link, t, states))
    {
      goOn(link.a, t);
      goOn(link.b, t);
      return;
    }
    partner_[link.a] = link.b;
    partner_[link.b] = link.a;
    links_.push_back(link);
  }

  std::pair<double, int> earliestOwnEvent() const
  {
    double earliest = NEVER;
    int mover = -1;
    for (std::size_t i = 0; i < movers_.size(); ++i)
      if (movers_[i].nextEventTime() < earliest)
      {
        earliest = movers_[i].nextEventTime();
        mover = static_cast<int>(i);
      }
    return {earliest, mover};
  }

  std::pair<double, std::pair<int, int>> earliestContact(double horizon)
  {
    double earliest = NEVER;
    std::pair<int, int> pair{-1, -1};
    for (std::size_t i = 0; i < movers_.size(); ++i)
      for (std::size_t j = i + 1; j < movers_.size(); ++j)
      {
        const double t = contactTime(i, j);
        if (t < earliest && t <= horizon)
        {
          earliest = t;
          pair = {static_cast<int>(i), static_cast<int>(j)};
        }
      }
    return {earliest, pair};
  }

  /// When balls i and j first meet on their current segments (cached while both segments stay).
  double contactTime(std::size_t i, std::size_t j)
  {
    PairContact& cached = pairs_[i * movers_.size() + j];
    const BallMover& a = movers_[i];
    const BallMover& b = movers_[j];
    if (cached.version_i == a.version() && cached.version_j == b.version())
      return cached.time;
    cached = {a.version(), b.version(), firstContact(a, b)};
    return cached.time;
  }

  double firstContact(const BallMover& a, const BallMover& b) const
  {
    using Status = BallMover::Status;
    if (a.status() == Status::Ended || b.status() == Status::Ended)
      return NEVER;
    if (a.status() != Status::Moving && b.status() != Status::Moving)
      return NEVER;  // two balls at rest stay apart (touching ones are part of the impact that reaches them)
    if (partner_[index(a)] == index(b))
      return NEVER;  // a linked pair stays in contact
    const double start = std::max(a.segment().start_time, b.segment().start_time);
    const double end = std::min(a.nextEventTime(), b.nextEventTime());
    const BallState sa = a.segment().at(start), sb = b.segment().at(start);
    const Eigen::Vector3d acceleration_a =
        a.status() == Status::Moving ? a.segment().acceleration : Eigen::Vector3d::Zero();
    const Eigen::Vector3d acceleration_b =
        b.status() == Status::Moving ? b.segment().acceleration : Eigen::Vector3d::Zero();
    const auto t = earliestBallContact(sb.position - sa.position, sb.velocity - sa.velocity,
                                       acceleration_b - acceleration_a, 2.0 * ball_.radius, end - start);
    return t ? start + *t : NEVER;
  }

  /// The impact of balls i and j with every ball touching them. Where the two press together and the meeting is
  /// the limit of a sequence of ever smaller collisions, the impact is that limit (ball–ball contacts plastic) and
  /// the pair goes on linked.
  Status collide(double t, int i, int j)
  {
    const bool limit =
        partner_[i] < 0 && partner_[j] < 0 && isSequenceLimit(pairPress(movers_[i].segment(), movers_[j].segment(), t));
    std::vector<int> cluster = touchingCluster(t, i, j);
    for (int k : cluster)
      if (partner_[k] >= 0)
        unlinkForImpact(k, t, cluster);
    std::vector<BallState> states;
    states.reserve(cluster.size());
    for (int k : cluster)
      states.push_back(movers_[k].segment().at(t));
    auto after =
        resolveBallImpact(states, ball_, table_, geometry_, limit ? plastic(contact_) : contact_, impactOptions());
    if (!after)
      return after.error();
    for (std::size_t k = 0; k < cluster.size(); ++k)
      movers_[cluster[k]].interrupt(t, after.value()[k], cluster[k] == i ? j : i);
    result_.ball_impacts.push_back({t, cluster});
    if (limit)
      startLink(t, i, j);
    return {};
  }

  /// A linked ball meets an impact: the link ends; a partner outside the impact goes on alone.
  void unlinkForImpact(int ball, double t, const std::vector<int>& cluster)
  {
    const int partner = partner_[ball];
    dissolve(linkOf(ball));
    if (std::find(cluster.begin(), cluster.end(), partner) == cluster.end())
      goOn(partner, t);
  }

  static BallContactSettings plastic(BallContactSettings contact)
  {
    contact.ball_ball.restitution = 0.0;
    return contact;
  }

  int index(const BallMover& mover) const { return static_cast<int>(&mover - movers_.data()); }

  /// Balls i and j and every ball touching them, directly or through others, at time t.
  std::vector<int> touchingCluster(double t, int i, int j) const
  {
    std::vector<int> cluster{i, j};
    for (std::size_t k = 0; k < cluster.size(); ++k)
    {
      const Eigen::Vector3d centre = movers_[cluster[k]].segment().at(t).position;
      for (std::size_t m = 0; m < movers_.size(); ++m)
      {
        if (movers_[m].status() == BallMover::Status::Ended ||
            std::find(cluster.begin(), cluster.end(), static_cast<int>(m)) != cluster.end())
          continue;
        const double gap = (movers_[m].segment().at(t).position - centre).norm() - 2.0 * ball_.radius;
        if (gap <= BALL_TOUCHING_TOLERANCE)
          cluster.push_back(static_cast<int>(m));
      }
    }
    return cluster;
  }

  SolverOptions impactOptions() const
  {
    SolverOptions options = p_.impact;
    options.max_seconds =
        std::max(std::chrono::duration<double>(deadline_ - std::chrono::steady_clock::now()).count(), 1e-6);
    return options;
  }

  const BallProperties& ball_;
  const Table& table_;
  const MotionGeometry& geometry_;
  const MotionParameters& p_;
  const BallContactSettings& contact_;
  Deadline deadline_;
  std::vector<BallMover> movers_;
  std::vector<PairContact> pairs_;  ///< [i * n + j], i < j
  std::vector<Link> links_;
  std::vector<int> partner_;  ///< the ball each ball is linked to, or -1
  TableTrajectory result_;
};
}  // namespace

Expected<TableTrajectory> runTableSimulation(const std::vector<TableBall>& balls, const BallProperties& ball,
                                             const Table& table, const MotionParameters& parameters,
                                             const BallContactSettings& contact)
{
  auto geometry = motionGeometry(table);
  if (!geometry)
    return geometry.error();
  return TableSimulation(balls, ball, table, geometry.value(), parameters, contact).run();
}

}  // namespace detail
}  // namespace billiard_shot_planner
