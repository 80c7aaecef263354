#pragma once

// The paper's method for the integrated shot (§8.2, Algorithm 1), as a baseline for the benchmarks only: every
// contact's springs advance with a fixed step of the primary impulse (the active contact with the larger k·E,
// footnote 18), one-step (Euler) integration, and every transition — end of compression (k ← k/e²), end of
// restitution, reactivation, stick ↔ slip — is detected at the end of the step in which it happens. The springs are
// those of the compliant model (docs/impact_model.md, Coulomb friction and tangential compliance): normal
// F_n = −k s_n, tangential −κ s_t in stick, −μF_n ŝ on the cone in slip. The secondary impulses follow from the
// springs rather than from the ratio √(k_s E_s / k_p E_p); the two are the same relation, and the step's length in
// time comes from δ = F_p dt + ½k_p|ṡ_p|dt², regular at the start where the paper solves a quadratic for the first
// slope. First order in the step, like the paper's own runs.
#include <Eigen/Dense>
#include <cmath>
#include <utility>
#include <vector>

#include "billiard_shot_planner/impact/impact_problem.hpp"

namespace paper_method
{
struct MasseResult
{
  Eigen::VectorXd velocity;
  long steps = 0;
};

namespace detail
{
enum class Phase
{
  Inactive,
  Compression,
  Restitution
};

struct Spring
{
  Eigen::Matrix<double, 3, Eigen::Dynamic> rows;  // tangent 1, tangent 2, normal
  double k, kappa, e, mu;
  Phase phase = Phase::Compression;
  bool slipping = false;
  double s_n = 0.0;
  Eigen::Vector2d s_t = Eigen::Vector2d::Zero();
  Eigen::Vector2d slip_direction = Eigen::Vector2d::UnitX();

  double normalForce() const { return phase == Phase::Inactive ? 0.0 : std::max(-k * s_n, 0.0); }
  double energy() const { return 0.5 * k * s_n * s_n; }
  Eigen::Vector2d direction() const { return s_t.norm() > 0.0 ? Eigen::Vector2d(s_t.normalized()) : slip_direction; }
  /// Force on body A in the contact frame (t1, t2, n).
  Eigen::Vector3d force() const
  {
    const double f_n = normalForce();
    const Eigen::Vector2d f_t = slipping ? Eigen::Vector2d(-mu * f_n * direction()) : Eigen::Vector2d(-kappa * s_t);
    return {f_t.x(), f_t.y(), f_n};
  }
};

inline void advanceSpring(Spring& c, const Eigen::Vector3d& w, double dt)
{
  if (c.phase == Phase::Inactive)
    return;
  const Eigen::Vector2d v_t = w.head<2>();
  c.s_n += w.z() * dt;
  if (!c.slipping)
  {
    c.s_t += v_t * dt;
    return;
  }
  const Eigen::Vector2d s_hat = c.direction();
  c.s_t += (v_t - s_hat * s_hat.dot(v_t)) * dt;  // turn toward the sliding velocity; length set on the cone
  c.s_t = c.s_t.normalized() * c.mu * c.normalForce() / c.kappa;
  c.slip_direction = c.direction();
}

inline void transitions(Spring& c, const Eigen::Vector3d& w)
{
  const double w_n = w.z();
  switch (c.phase)
  {
    case Phase::Inactive:
      if (w_n < 0.0)
      {
        c.phase = Phase::Compression;
        c.s_n = 0.0;
        c.s_t.setZero();
        c.slipping = false;
      }
      return;
    case Phase::Compression:
      if (w_n >= 0.0)
      {
        c.phase = Phase::Restitution;
        c.k /= c.e * c.e;  // force continuous: s_n ← e² s_n
        c.s_n *= c.e * c.e;
      }
      break;
    case Phase::Restitution:
      if (c.s_n >= 0.0)
      {
        c.phase = Phase::Inactive;
        c.s_n = 0.0;
        c.s_t.setZero();
        return;
      }
      if (w_n < 0.0)
        c.phase = Phase::Compression;
      break;
  }
  if (c.mu <= 0.0)
    return;
  const double eta2 = c.k / c.kappa;
  if (!c.slipping && c.kappa * c.s_t.norm() > c.mu * c.normalForce())
  {
    c.slipping = true;
    c.slip_direction = c.direction();
  }
  else if (c.slipping && c.direction().dot(w.head<2>()) + c.mu * eta2 * w_n <= 0.0)
    c.slipping = false;
}
/// The primary contact (footnote 18): the active one with the largest k·E; where no spring is loaded yet, the one
/// approaching fastest. Ties keep the first.
inline const Spring* primarySpring(const std::vector<Spring>& springs, const Eigen::VectorXd& u)
{
  auto priority = [&u](const Spring& s)
  { return s.energy() > 0.0 ? std::make_pair(1.0, s.k * s.energy()) : std::make_pair(0.0, -(s.rows.row(2) * u)(0)); };
  const Spring* primary = nullptr;
  for (const Spring& s : springs)
    if (s.phase != Phase::Inactive && (!primary || priority(s) > priority(*primary)))
      primary = &s;
  return primary;
}
}  // namespace detail

/// Solves a problem of frictional 3-D contacts (the cue strike) with the primary-impulse step `step` (N·s).
inline MasseResult solveMasse(const billiard_shot_planner::ImpactProblem& problem, double step)
{
  using detail::Phase;
  const Eigen::MatrixXd inverse_mass = problem.mass_matrix.inverse();
  std::vector<detail::Spring> springs;
  for (const auto& contact : problem.contacts)
  {
    detail::Spring s;
    s.rows.resize(3, problem.velocity.size());
    s.rows << contact.tangent, contact.normal;
    s.k = contact.law.stiffness;
    s.kappa = contact.law.stiffness / contact.law.eta2;
    s.e = contact.law.restitution;
    s.mu = contact.law.friction;
    springs.push_back(s);
  }
  Eigen::VectorXd u = problem.velocity;
  MasseResult result;
  // The tip's contact point slips from the first instant when |v_t| > μη²|v_n| (a miscue), else every contact sticks.
  for (auto& s : springs)
  {
    const Eigen::Vector3d w = s.rows * u;
    s.phase = w.z() <= 0.0 ? Phase::Compression : Phase::Inactive;
    if (s.mu > 0.0 && w.head<2>().norm() > s.mu * (s.k / s.kappa) * -w.z())
    {
      s.slipping = true;
      s.slip_direction = w.head<2>().normalized();
    }
  }
  auto anyActive = [&]
  {
    for (const auto& s : springs)
      if (s.phase != Phase::Inactive)
        return true;
    return false;
  };
  while (anyActive() && result.steps < 200000000)
  {
    ++result.steps;
    const detail::Spring* primary = detail::primarySpring(springs, u);
    const double approach = std::max(-(primary->rows.row(2) * u)(0), 0.0);
    const double force = primary->normalForce();
    const double dt = 2.0 * step / (force + std::sqrt(force * force + 2.0 * primary->k * approach * step));
    Eigen::VectorXd impulse = Eigen::VectorXd::Zero(u.size());
    for (auto& s : springs)
    {
      detail::advanceSpring(s, s.rows * u, dt);
      impulse += s.rows.transpose() * (s.force() * dt);
    }
    u += inverse_mass * impulse;
    for (auto& s : springs)
      detail::transitions(s, s.rows * u);
  }
  result.velocity = u;
  return result;
}

}  // namespace paper_method
