#pragma once

// A shot played many times with the robot's execution noise: its pot probability.
#include <string>
#include <vector>

#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace planning
{
/// Wilson's score interval of a binomial proportion at 95 %: unlike the normal approximation it stays inside
/// [0, 1] and is sensible at 0 or n successes.
struct PotEstimate
{
  int successes = 0;
  int trials = 0;

  double probability() const { return trials > 0 ? static_cast<double>(successes) / trials : 0.0; }
  double low() const;
  double high() const;
};

/// The rollouts of one shot: the noisy strokes are drawn up front from the seed, so that the estimate does not
/// depend on how the rollouts are spread over threads or batches.
class NoisyRollouts
{
public:
  /// `count` noisy strokes of `nominal`, drawn from `seed`.
  NoisyRollouts(const Stroke& nominal, std::string target, int pocket, unsigned seed, int count,
                const PlanContext& context);

  /// Plays up to `count` more rollouts on `threads` threads; those not started by `deadline` are not played.
  void play(int count, int threads, Clock::time_point deadline);
  bool finished() const { return next_ >= strokes_.size(); }
  const PotEstimate& estimate() const { return estimate_; }
  /// Where the target ended in each rollout played.
  const std::vector<Eigen::Vector2d>& targetEndPoints() const { return end_points_; }

private:
  std::vector<Stroke> strokes_;
  std::string target_;
  int pocket_;
  const PlanContext& context_;
  std::size_t next_ = 0;
  PotEstimate estimate_;
  std::vector<Eigen::Vector2d> end_points_;
};

}  // namespace planning
}  // namespace billiard_shot_planner
