#include "sampled_crossing_search.hpp"

#include <algorithm>

namespace billiard_shot_planner
{
namespace detail
{
const std::vector<FiredGuard>& earliestCrossings(const std::vector<FiredGuard>& crossings, double width,
                                                 std::vector<FiredGuard>& fired)
{
  fired.clear();
  if (crossings.empty())
    return fired;
  double first = crossings.front().time;
  for (const FiredGuard& c : crossings)
    first = std::min(first, c.time);
  for (const FiredGuard& c : crossings)
    if (c.time <= first + SIMULTANEOUS * width)
      fired.push_back({c.guard, first});
  return fired;
}

SampledCrossingSearch::SampledCrossingSearch(const ContactSpace& space, const std::vector<ContactState>& contacts,
                                             const ContactDynamics& dynamics, std::size_t state_size)
    : space_(space), contacts_(contacts), dynamics_(dynamics), state_(state_size)
{
}

void SampledCrossingSearch::startNextStep(double t0, double t1)
{
  previous_time_ = sampleTime(t0, t1, samples_ - 1);
  previous_row_ = guard_values_.row(samples_ - 1);
  previous_row_known_ = true;
  guard_values_.row(0) = guard_values_.row(samples_);
  first_row_known_ = true;
}

int SampledCrossingSearch::guardSamples(const SeparationClockStepper& stepper, double u0, double u1) const
{
  const double half_radians = 2.0 * omega_ * (stepper.timeAt(u1) - stepper.timeAt(u0));
  return SAMPLES_PER_STEP * static_cast<int>(std::clamp(std::ceil(half_radians), 1.0, MAX_STEP_SUBDIVISION));
}

double SampledCrossingSearch::resolvedGuard(const Guard& guard, const Kinematics& kinematics) const
{
  const double value = guardValue(guard, kinematics, contacts_, dynamics_, space_);
  return guard.type == ContactEventType::EndOfCompression ? value - separation_floor_ : value;
}

void SampledCrossingSearch::storeGuardRow(int k)
{
  for (std::size_t g = 0; g < guards_->size(); ++g)
    guard_values_(k, static_cast<Eigen::Index>(g)) = resolvedGuard((*guards_)[g], kinematics_);
}

}  // namespace detail
}  // namespace billiard_shot_planner
