#include "noisy_rollouts.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <thread>

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
constexpr double Z95 = 1.959963984540054;

double wilsonBound(const PotEstimate& e, double sign)
{
  if (e.trials == 0)
    return sign > 0.0 ? 1.0 : 0.0;
  const double n = e.trials, p = e.probability(), z2 = Z95 * Z95;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = Z95 * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / (1.0 + z2 / n);
  return std::clamp(centre + sign * half, 0.0, 1.0);
}

}  // namespace

// The interval holds the estimate (it always does, but at 0 or n successes only to round-off).
double PotEstimate::low() const
{
  return std::min(wilsonBound(*this, -1.0), probability());
}

double PotEstimate::high() const
{
  return std::max(wilsonBound(*this, 1.0), probability());
}

NoisyRollouts::NoisyRollouts(const Stroke& nominal, std::string target, int pocket, unsigned seed, int count,
                             const PlanContext& context)
    : target_(std::move(target)), pocket_(pocket), context_(context)
{
  std::mt19937_64 random(seed);
  const auto strokes = static_cast<std::size_t>(std::max(count, 0));
  strokes_.reserve(strokes);
  for (std::size_t k = 0; k < strokes; ++k)
    strokes_.push_back(noisyStroke(nominal, context.request.noise, context.radius(), random));
}

void NoisyRollouts::play(int count, int threads, Clock::time_point deadline)
{
  const std::size_t begin = next_, end = std::min(strokes_.size(), next_ + static_cast<std::size_t>(count));
  std::vector<signed char> pots(end - begin, -1);  // −1: not played (the deadline came first)
  std::vector<Eigen::Vector2d> ends(end - begin, Eigen::Vector2d::Zero());
  std::atomic<std::size_t> claim{begin};
  auto worker = [&]()
  {
    for (std::size_t k = claim++; k < end; k = claim++)
    {
      if (context_.shouldStop(deadline))
        return;
      const Stroke& stroke = strokes_[k];
      StrokeEvaluation played;
      if (stroke.speed > 0.0)
        played = evaluateStroke(stroke, target_, pocket_, context_);
      pots[k - begin] = played.pots ? 1 : 0;
      ends[k - begin] = played.valid ? played.target_end : Eigen::Vector2d::Constant(NAN);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(threads, 1); ++t)
    pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool)
    thread.join();
  // Only the unbroken run of played rollouts counts: the estimate is the same whichever thread was late.
  for (std::size_t k = 0; k < pots.size() && pots[k] >= 0; ++k)
  {
    ++next_;
    ++estimate_.trials;
    estimate_.successes += pots[k];
    if (ends[k].allFinite())
      end_points_.push_back(ends[k]);
  }
  if (next_ < end)
    next_ = strokes_.size();  // out of time: no more rollouts of this shot
}

}  // namespace planning
}  // namespace billiard_shot_planner
