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

/// The largest value over u ∈ [0, width] of the cubic g + ġu + g̈u²/2 + Ju³/6 (J ≥ 0): Taylor's bound on a guard to
/// third order, from one end of an interval.
double largestOfCubic(double value, double rate, double acceleration, double jerk, double width)
{
  const auto at = [&](double u) { return value + u * (rate + u * (0.5 * acceleration + u * jerk / 6.0)); };
  double largest = std::max(value, at(width));
  // Its local maximum: where the rate ġ + g̈u + Ju²/2 falls through zero.
  double peak = -1.0;
  if (jerk > 0.0)
  {
    const double discriminant = acceleration * acceleration - 2.0 * jerk * rate;
    if (discriminant >= 0.0)
      peak = (-acceleration - std::sqrt(discriminant)) / jerk;
  }
  else if (acceleration < 0.0)
    peak = -rate / acceleration;
  if (peak > 0.0 && peak < width)
    largest = std::max(largest, at(peak));
  return largest;
}
}  // namespace

bool AffineCrossingSearch::start(const LinearPhaseStepper& stepper, const PerGuard<std::optional<AffineGuard>>& forms,
                                 double t)
{
  stepper_ = &stepper;
  t_ = t;
  guards_.clear();
  bounds_.clear();
  noise_.clear();
  for (const std::optional<AffineGuard>& form : forms)
  {
    guards_.push_back(*form);
    bounds_.push_back(stepper.affineGuardBounds(*form));
    noise_.push_back(NOISE * bounds_.back().second * stepper.step() * stepper.step());
  }
  start_ = 0;
  sampleAll(t, ends_[start_]);
  for (Sample& start : ends_[start_])
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
  const PerGuard<Sample>& at_start = ends_[start_];
  PerGuard<Sample>& at_end = ends_[1 - start_];
  sampleAll(b, at_end);
  brackets_.clear();
  pending_[0].resize(guards_.size());
  std::iota(pending_[0].begin(), pending_[0].end(), std::size_t{0});
  isolate(a, at_start, b, at_end, 0);
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
  start_ = 1 - start_;
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
  const LinearPhaseStepper::GuardValue at = stepper_->affineGuard<true>(guards_[g]);
  return {at.value, at.rate, at.acceleration};
}

AffineCrossingSearch::Sample AffineCrossingSearch::sampleValue(std::size_t g) const
{
  const LinearPhaseStepper::GuardValue at = stepper_->affineGuard<false>(guards_[g]);
  return {at.value, at.rate, 0.0};
}

AffineCrossingSearch::Crossing AffineCrossingSearch::classify(std::size_t g, double a, Sample ga, double b, Sample gb,
                                                              bool last) const
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
  // Above its round-off at the start of an interval, the guard has risen out of it by then, no later: the interval
  // before was left within twice its round-off (see MAX_REFINEMENTS). Undecided, no bound could ever exclude it,
  // and every interval after it in the step would be halved, both halves and theirs, down to the last halving.
  if (va > 0.0)
    return Crossing::Bracketed;
  if (va == 0.0 && vb == 0.0 && std::max(std::abs(ga.rate), std::abs(gb.rate)) * half <= noise)
    return Crossing::Excluded;
  // The chord's bound: g exceeds the chord between its ends by at most Mh²/8. It decides what is left once the
  // interval is short (see MAX_REFINEMENTS), whatever the rates.
  const double curvature_term = 0.5 * bounds_[g].second * half * half;
  if (std::max(va, vb) + curvature_term <= noise)
    return Crossing::Excluded;
  // Taylor's bounds from each end over its half of the interval: to second order largest at an end of the half (it
  // is convex), to third order where the cubic peaks.
  const double jerk = bounds_[g].third;
  const double left = std::min(ga.value + ga.rate * half + curvature_term,
                               largestOfCubic(ga.value, ga.rate, ga.acceleration, jerk, half));
  const double right = std::min(gb.value - gb.rate * half + curvature_term,
                                largestOfCubic(gb.value, -gb.rate, gb.acceleration, jerk, half));
  const bool left_clear = std::max(va, left) <= noise;
  const bool right_clear = std::max(vb, right) <= noise;
  if (left_clear && right_clear)
    return Crossing::Excluded;
  // Undecided after the last halving, the guard rises out of its round-off within the interval: its zero is there.
  if (last && va == 0.0 && vb > 0.0)
    return Crossing::Bracketed;
  return Crossing::Undecided;
}

bool AffineCrossingSearch::taylorExcludes(std::size_t g, double a, Sample ga, double b, Sample gb) const
{
  constexpr int N = LinearPhaseStepper::TAYLOR_ORDER;
  const double h = b - a;
  const double noise = noise_[g];
  double remainder = bounds_[g].highest;
  for (int k = 1; k <= N; ++k)
    remainder *= h / k;
  double derivatives[N];
  for (const bool left : {true, false})
  {
    // g(end ± u) = Σ g⁽ᵏ⁾(end)(±u)ᵏ/k! + R, |R| ≤ M_N uᴺ/N!: at most its value plus the terms that can raise it, each
    // largest at u = h.
    const Sample& at = left ? ga : gb;
    derivatives[0] = at.value;
    derivatives[1] = at.rate;
    stepper_->affineGuardDerivatives(guards_[g], left ? a : b, derivatives);
    const double direction = left ? 1.0 : -1.0;
    double bound = derivatives[0] + remainder, power = 1.0, sign = 1.0;
    for (int k = 1; k < N; ++k)
    {
      power *= h / k;
      sign *= direction;
      bound += std::max(0.0, sign * derivatives[k]) * power;
    }
    if (bound <= noise)
      return true;
  }
  return false;
}

bool AffineCrossingSearch::isolate(double a, const PerGuard<Sample>& at_a, double b, const PerGuard<Sample>& at_b,
                                   int depth)
{
  if (std::chrono::steady_clock::now() > deadline_)
    return false;
  PerGuard<std::size_t>& undecided = pending_[depth + 1];
  undecided.clear();
  bool found = false;
  for (std::size_t g : pending_[depth])
    switch (classify(g, a, at_a[g], b, at_b[g], depth == MAX_REFINEMENTS))
    {
      case Crossing::Bracketed:
        brackets_.push_back({g, a, b, at_a[g].value, at_b[g].value});
        found = true;
        break;
      case Crossing::Undecided:
        if (depth >= TAYLOR_DEPTH && taylorExcludes(g, a, at_a[g], b, at_b[g]))
          break;
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
  const double value = sampleValue(bracket.guard).value - bracket.level;
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
  // Once Newton's method has converged, a point just past the zero, on the other side from t, closes the bracket.
  // Where the guard is flat within its round-off over more than the tolerance (a zero touched nearly tangentially)
  // that point lands on the same side, and so would every further one, each moving one end by a quarter of the
  // tolerance: the bracket is bisected from then on. Otherwise the iterations run out and the bracket's far end,
  // 2.5e-5 from the zero in velocity, is taken for the zero: a plastic contact becomes a rigid link while it
  // separates (project issue 23).
  bool bisecting = false;
  double nudged_from = 0.0;  ///< sign of the guard where the last point past the zero was aimed from, or 0
  for (int i = 0; i < MAX_ROOT_ITERATIONS && b - a > tolerance; ++i)
  {
    stepper_->moveTo(t);
    const Sample at_t = sampleValue(bracket.guard);
    const double value = at_t.value - bracket.level;
    const double side = value > 0.0 ? 1.0 : -1.0;
    (side > 0.0 ? b : a) = t;
    bisecting = bisecting || side == nudged_from;
    const double step = -value / at_t.rate;
    const bool converged = std::abs(step) <= 0.25 * tolerance;
    nudged_from = converged ? side : 0.0;
    const double next = t + step - (converged ? 0.25 * side * tolerance : 0.0);
    t = !bisecting && next > a && next < b ? next : 0.5 * (a + b);
  }
  return b;
}

}  // namespace detail
}  // namespace billiard_shot_planner
