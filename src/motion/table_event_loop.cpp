#include "table_event_loop.hpp"

#include <algorithm>
#include <limits>

#include "ball_contact_time.hpp"
#include "ball_mover.hpp"
#include "table_collisions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
constexpr double NEVER = std::numeric_limits<double>::infinity();

/// The event loop over all balls. Pair contact times are cached and recomputed only when one of the two balls'
/// segments has changed.
class TableSimulation
{
public:
  TableSimulation(const std::vector<TableBall>& balls, const BallProperties& ball, const Table& table,
                  const MotionParameters& p, const BallContactSettings& contact)
      : ball_(ball), table_(table), p_(p), contact_(contact), deadline_(deadlineAfter(p.impact.max_seconds))
  {
    movers_.reserve(balls.size());
    for (const TableBall& b : balls)
    {
      result_.ids.push_back(b.id);
      movers_.emplace_back(ball_, table_, p_, deadline_);
    }
    for (std::size_t i = 0; i < balls.size(); ++i)
      movers_[i].begin(balls[i].state);
    pairs_.assign(balls.size() * balls.size(), PairContact{});
  }

  Expected<TableTrajectory> run()
  {
    while (true)
    {
      const auto [own_time, mover] = earliestOwnEvent();
      const auto [contact_time, pair] = earliestContact(own_time);
      if (contact_time < own_time)
      {
        if (Status status = collide(contact_time, pair.first, pair.second); !status)
          return status.error();
        continue;
      }
      if (mover < 0)
        break;
      auto ended = movers_[mover].runOwnEvent();
      if (!ended)
        return ended.error();
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

  Status collide(double t, int i, int j)
  {
    std::vector<int> cluster = touchingCluster(t, i, j);
    std::vector<BallState> states;
    states.reserve(cluster.size());
    for (int k : cluster)
      states.push_back(movers_[k].segment().at(t));
    auto after = resolveBallImpact(states, ball_, table_, contact_, impactOptions());
    if (!after)
      return after.error();
    for (std::size_t k = 0; k < cluster.size(); ++k)
      movers_[cluster[k]].interrupt(t, after.value()[k], cluster[k] == i ? j : i);
    result_.ball_impacts.push_back({t, cluster});
    return {};
  }

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
  const MotionParameters& p_;
  const BallContactSettings& contact_;
  Deadline deadline_;
  std::vector<BallMover> movers_;
  std::vector<PairContact> pairs_;  ///< [i * n + j], i < j
  TableTrajectory result_;
};
}  // namespace

Expected<TableTrajectory> runTableSimulation(const std::vector<TableBall>& balls, const BallProperties& ball,
                                             const Table& table, const MotionParameters& parameters,
                                             const BallContactSettings& contact)
{
  return TableSimulation(balls, ball, table, parameters, contact).run();
}

}  // namespace detail
}  // namespace billiard_shot_planner
