#include "affine_crossing_search.hpp"

#include <algorithm>
#include <numeric>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Relative round-off of an affine guard's modal sum: values below it times the size of the guard's modal terms
/// over a step (its curvature bound times the step squared) are zero.
constexpr double NOISE = 1e-12;

/// Newton iterations allowed for one zero (about five are needed).
constexpr int MAX_ROOT_ITERATIONS = 100;
}  // namespace

bool AffineCrossingSearch::start(const LinearPhaseStepper& stepper, const PerGuard<std::optional<AffineGuard>>& forms,
                                 double t)
{
  stepper_ = &stepper;
  t_ = t;
  guards_.clear();
  curvature_.clear();
  noise_.clear();
  for (const std::optional<AffineGuard>& form : forms)
  {
    guards_.push_back(*form);
    curvature_.push_back(stepper.affineGuardCurvature(*form));
    noise_.push_back(NOISE * curvature_.back() * stepper.step() * stepper.step());
  }
  sampleAll(t, at_start_);
  for (Sample& start : at_start_)
  {
    // The contact that has just switched starts its new guard at zero, falling, but the state it switched at was
    // found with the old state's modes and is re-read by the new one's: up to round-off on either side of zero.
    if (start.value > 0.0 && start.value <= START_ROUND_OFF && start.rate < 0.0)
      start.value = 0.0;
    if (start.value > 0.0)
      return false;
  }
  return true;
}

const PerGuard<GuardZero>& AffineCrossingSearch::nextStep()
{
  const double a = t_, b = t_ + stepper_->step();
  sampleAll(b, at_end_);
  brackets_.clear();
  pending_[0].resize(guards_.size());
  std::iota(pending_[0].begin(), pending_[0].end(), std::size_t{0});
  isolate(a, at_start_, b, at_end_, 0);
  zeros_.clear();
  double earliest = b;
  for (Bracket& bracket : brackets_)
  {
    if (!endBy(earliest + SIMULTANEOUS * (b - a), bracket))
      continue;
    zeros_.push_back({bracket.guard, risingZero(bracket)});
    earliest = std::min(earliest, zeros_.back().time);
  }
  t_ = b;
  std::swap(at_start_, at_end_);
  return zeros_;
}

void AffineCrossingSearch::sampleAll(double t, PerGuard<Sample>& samples) const
{
  stepper_->moveTo(t);
  samples.clear();
  for (std::size_t g = 0; g < guards_.size(); ++g)
    samples.push_back(sample(g));
}

AffineCrossingSearch::Sample AffineCrossingSearch::sample(std::size_t g) const
{
  const auto [value, rate] = stepper_->affineGuard(guards_[g]);
  return {value, rate};
}

AffineCrossingSearch::Crossing AffineCrossingSearch::classify(std::size_t g, double a, Sample ga, double b,
                                                              Sample gb) const
{
  // Values within round-off of the guard's modal terms count as zero: a contact not reached yet (the far end of a
  // chain) has a velocity that is a sum of cancelling modes, and its sign is noise. From zero, only a guard that
  // rises leaves at once; one that falls crosses later, if at all; one that stays there does not cross.
  const double half = 0.5 * (b - a);
  const double noise = noise_[g];
  const double va = std::abs(ga.value) <= noise ? 0.0 : ga.value;
  const double vb = std::abs(gb.value) <= noise ? 0.0 : gb.value;
  const bool below = va < 0.0 || (va == 0.0 && ga.rate * half > noise);
  if (below && vb > 0.0)
    return Crossing::Bracketed;
  if (va == 0.0 && vb == 0.0 && std::max(std::abs(ga.rate), std::abs(gb.rate)) * half <= noise)
    return Crossing::Excluded;
  // Taylor's bound from each end over its half of the interval, largest at an end of the half (it is convex).
  const double curvature_term = 0.5 * curvature_[g] * half * half;
  const bool left_clear = std::max(va, ga.value + ga.rate * half + curvature_term) <= noise;
  const bool right_clear = std::max(vb, gb.value - gb.rate * half + curvature_term) <= noise;
  return left_clear && right_clear ? Crossing::Excluded : Crossing::Undecided;
}

bool AffineCrossingSearch::isolate(double a, const PerGuard<Sample>& at_a, double b, const PerGuard<Sample>& at_b,
                                   int depth)
{
  PerGuard<std::size_t>& undecided = pending_[depth + 1];
  undecided.clear();
  bool found = false;
  for (std::size_t g : pending_[depth])
    switch (classify(g, a, at_a[g], b, at_b[g]))
    {
      case Crossing::Bracketed:
        brackets_.push_back({g, a, b, at_a[g].value, at_b[g].value});
        found = true;
        break;
      case Crossing::Undecided:
        if (depth < MAX_REFINEMENTS)
          undecided.push_back(g);
        else if (std::abs(at_a[g].value) <= noise_[g] && at_b[g].value > noise_[g])
          found = bracketRiseFromZero(g, a, b, at_b[g].value) || found;
        break;
      case Crossing::Excluded:
        break;
    }
  if (undecided.empty())
    return found;
  // One evaluation of the modes serves every undecided guard. The right half is searched only when the left one
  // holds no bracket: its zeros come later.
  const double middle = 0.5 * (a + b);
  PerGuard<Sample>& at_middle = at_middle_[depth];
  at_middle.resize(at_a.size());
  stepper_->moveTo(middle);
  for (std::size_t g : undecided)
    at_middle[g] = sample(g);
  if (isolate(a, at_a, middle, at_middle, depth + 1))
    return true;
  return isolate(middle, at_middle, b, at_b, depth + 1) || found;
}

bool AffineCrossingSearch::bracketRiseFromZero(std::size_t g, double a, double b, double gb)
{
  // Its rise is bracketed above its value at a and round-off (it may start just above zero, taken for zero when
  // falling by start): the zero the interval brackets is then the rise's, after any dip, and it lies after a. A rise
  // found at a itself would fire at the same instant for ever: a reactivated rigid link that no force presses yet is
  // released at once.
  stepper_->moveTo(a);
  const double at_a = sample(g).value;
  const double level = std::max(at_a, 0.0) + noise_[g];
  if (!(gb > level))
    return false;
  brackets_.push_back({g, a, b, at_a - level, gb - level, level});
  return true;
}

bool AffineCrossingSearch::endBy(double limit, Bracket& bracket) const
{
  if (limit >= bracket.b)
    return true;
  if (limit <= bracket.a)
    return false;
  stepper_->moveTo(limit);
  const double value = sample(bracket.guard).value - bracket.level;
  if (value <= 0.0)
    return false;
  bracket.b = limit;
  bracket.gb = value;
  return true;
}

double AffineCrossingSearch::risingZero(Bracket bracket) const
{
  double &a = bracket.a, &b = bracket.b;
  if (bracket.ga >= 0.0)
    return a;  // rising from zero (to round-off) at a
  const double tolerance = rootTolerance(b - a, a);
  double t = a - bracket.ga * (b - a) / (bracket.gb - bracket.ga);
  for (int i = 0; i < MAX_ROOT_ITERATIONS && b - a > tolerance; ++i)
  {
    stepper_->moveTo(t);
    const Sample at_t = sample(bracket.guard);
    const double value = at_t.value - bracket.level;
    (value > 0.0 ? b : a) = t;
    // Once converged the zero lies well within the tolerance of t + step: a point just past it, on the other side
    // from t, closes the bracket. A step that would leave the bracket bisects it.
    const double step = -value / at_t.rate;
    const double past = std::abs(step) <= 0.25 * tolerance ? (value > 0.0 ? -0.25 : 0.25) * tolerance : 0.0;
    const double next = t + step + past;
    t = next > a && next < b ? next : 0.5 * (a + b);
  }
  return b;
}

}  // namespace detail
}  // namespace billiard_shot_planner
