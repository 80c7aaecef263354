#pragma once

// The paper's own numerical method, as a baseline for the benchmarks only: the frictionless ball–ball–table
// collision integrated with a fixed step over the primary impulse (§4, Algorithm 1 with the primary impulse chosen
// as in footnote 18: the contact with the larger k·E), energies by eq. (5), the secondary impulse by eq. (15), and
// the start of S1 by the closed-form slope of eq. (27). No event location: every transition is detected at the
// end of the step in which it happens, so the error is first order in the step.
#include <cmath>

namespace paper_method
{
struct Result
{
  double v1, v2;
  long steps;
};

inline Result solve(double m1, double m2, double ratio, double e1, double e2, double v0, double step)
{
  double k[2] = {1.0, ratio}, E[2] = {0.0, 0.0}, I[2] = {0.0, 0.0}, e[2] = {e1, e2};
  bool active[2] = {true, true}, compressing[2] = {true, true};
  auto velocities = [&](double& v1, double& v2)
  {
    v1 = v0 + I[0] / m1;
    v2 = (I[1] - I[0]) / m2;
  };
  // Normal velocity of each contact (ẋ1 = v1 − v2, ẋ2 = v2); approach is negative.
  auto rates = [&](double out[2])
  {
    double v1, v2;
    velocities(v1, v2);
    out[0] = v1 - v2;
    out[1] = v2;
  };
  long steps = 0;
  while ((active[0] || active[1]) && steps < 100000000)
  {
    ++steps;
    double rate[2];
    rates(rate);
    // The primary impulse: the only active contact, or the one with the larger k·E (footnote 18).
    int p = active[0] && (!active[1] || k[0] * E[0] >= k[1] * E[1]) ? 0 : 1;
    int s = 1 - p;
    double ds = 0.0;
    double v1, v2;
    velocities(v1, v2);
    // Where the secondary spring is still relaxed its slope is zero: the closed-form first-step slopes of the
    // paper's §4.2 (eq. 27 and its analogues after S2 and S3; docs/validation.md, The paper's fixed-step method).
    auto slope = [&](double r, double b) { return 2.0 * r / (b + std::sqrt(b * b + 4.0 * r)); };
    if (active[s] && E[s] > 0.0 && E[p] > 0.0)
      ds = step * std::sqrt(k[s] * E[s] / (k[p] * E[p]));
    else if (active[s] && E[p] == 0.0)  // start of S1
      ds = step * slope(k[1] / k[0], -2.0 * m2 * v0 / step - 1.0 - m2 / m1 + k[1] / k[0]);
    else if (active[s] && s == 0)  // S1 after S2: the ball–ball contact starts again
      ds = step * slope(k[0] / k[1],
                        2.0 * m2 * E[1] / (step * step) - 2.0 * m2 * v2 / step - 1.0 + k[0] / k[1] * (1.0 + m2 / m1));
    else if (active[s])  // S1 after S3: the ball–table contact starts again
      ds = step *
           slope(k[1] / k[0], 2.0 * m2 * E[0] / (step * step) - 2.0 * m2 * v1 / step - 1.0 - m2 / m1 + k[1] / k[0]);
    const double d[2] = {p == 0 ? step : ds, p == 0 ? ds : step};
    for (int c = 0; c < 2; ++c)
      if (active[c])
      {
        I[c] += d[c];
        E[c] -= rate[c] * d[c];  // eq. (5): dE/dI = −ẋ
      }
    double after[2];
    rates(after);
    for (int c = 0; c < 2; ++c)
    {
      if (!active[c])
      {
        if (after[c] < 0.0)
        {
          active[c] = compressing[c] = true;  // reactivation keeps k
          E[c] = 0.0;
        }
        continue;
      }
      if (compressing[c] && after[c] >= 0.0)
      {
        compressing[c] = false;  // end of compression: k ← k/e², E ← e²E
        k[c] /= e[c] * e[c];
        E[c] *= e[c] * e[c];
      }
      else if (!compressing[c] && after[c] < 0.0)
        compressing[c] = true;  // restart of compression
      if (!compressing[c] && E[c] <= 0.0)
      {
        active[c] = false;
        E[c] = 0.0;
      }
    }
  }
  Result result{0.0, 0.0, steps};
  velocities(result.v1, result.v2);
  return result;
}

}  // namespace paper_method
