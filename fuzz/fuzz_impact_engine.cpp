// libFuzzer target: an ImpactProblem and SolverOptions straight from the bytes (format: engine_input.hpp), checked by
// validate() and solved by solveMultipleImpact(). Aborts, so that libFuzzer records the input, when
//  - the solver accepts a problem or options that validate() refuses,
//  - a successful result has non-finite or missized velocities, impulses or energies,
//  - the final kinetic energy exceeds the initial one by more than 1e-6 of it.
// Crashes, leaks and undefined behaviour are the sanitizers'; hangs are libFuzzer's -timeout. FUZZ_VERBOSE=1 in the
// environment prints each input's outcome and, for a refused problem, validate()'s reason.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "engine_input.hpp"

namespace
{
using billiard_shot_planner::ContactImpulse;
using billiard_shot_planner::ImpactResult;
using billiard_shot_planner::Status;
using fuzz_engine::EngineInput;

constexpr double ENERGY_SLACK = 1e-6;

std::string describe(const EngineInput& input)
{
  const Eigen::IOFormat full(17, 0, ", ", "; ", "", "", "[", "]");
  std::ostringstream text;
  text.precision(17);
  const auto& p = input.problem;
  text << "mass_matrix " << p.mass_matrix.format(full) << "\nvelocity " << p.velocity.transpose().format(full) << "\n";
  for (std::size_t i = 0; i < p.contacts.size(); ++i)
  {
    const auto& c = p.contacts[i];
    text << "contact " << i << ": normal " << c.normal.format(full) << " tangent " << c.tangent.format(full) << " e "
         << c.law.restitution << " k " << c.law.stiffness << " mu " << c.law.friction << " eta2 " << c.law.eta2 << "\n";
  }
  const auto& o = input.options;
  text << "options: rtol " << o.relative_tolerance << " atol " << o.absolute_tolerance << " closed_form "
       << o.closed_form_linear_phases << " separation_clock " << o.separation_clock << " quasi_steady "
       << o.quasi_steady_slip << " record_samples " << o.record_samples << " max_events " << o.max_events
       << " max_steps " << o.max_steps << " chatter " << o.chatter_energy_fraction << " " << o.chatter_stiffness_growth
       << " " << o.chatter_resolution << "\n";
  return text.str();
}

[[noreturn]] void fail(const EngineInput& input, const std::string& what)
{
  std::fprintf(stderr, "fuzz_impact_engine: %s\n%s", what.c_str(), describe(input).c_str());
  std::abort();
}

double kineticEnergy(const Eigen::MatrixXd& mass, const Eigen::VectorXd& u)
{
  return 0.5 * u.dot(mass * u);
}

void checkResult(const EngineInput& input, const ImpactResult& r)
{
  const auto& p = input.problem;
  if (r.velocity.size() != p.velocity.size() || !r.velocity.allFinite())
    fail(input, "a successful result has missized or non-finite velocities");
  if (r.impulses.size() != p.contacts.size())
    fail(input, "a successful result has one impulse per contact missing");
  for (const ContactImpulse& impulse : r.impulses)
    if (!std::isfinite(impulse.normal) || !impulse.tangential.allFinite())
      fail(input, "a successful result has a non-finite impulse");
  if (!std::isfinite(r.initial_kinetic_energy) || !std::isfinite(r.final_kinetic_energy))
    fail(input, "a successful result reports a non-finite kinetic energy");
  const double initial = kineticEnergy(p.mass_matrix, p.velocity);
  const double final = kineticEnergy(p.mass_matrix, r.velocity);
  if (!(final <= initial * (1.0 + ENERGY_SLACK)))
  {
    std::ostringstream what;
    what.precision(17);
    what << "kinetic energy grew: initial " << initial << ", final " << final << " (relative gain "
         << (final - initial) / initial << "; the result reports " << r.initial_kinetic_energy << " -> "
         << r.final_kinetic_energy << ", " << r.events.size() << " events, converged " << r.converged
         << ")\nfinal velocity " << r.velocity.transpose().format(Eigen::IOFormat(17)) << "";
    fail(input, what.str());
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const bool verbose = std::getenv("FUZZ_VERBOSE") != nullptr;
  FuzzedDataProvider in(data, size);
  const EngineInput input = fuzz_engine::readEngineInput(in);
  const Status problem_check = validate(input.problem);
  const Status options_check = validate(input.options);
  const auto result = billiard_shot_planner::solveMultipleImpact(input.problem, input.options);
  if (!problem_check || !options_check)
  {
    if (verbose)
      std::fprintf(stderr, "invalid: %s\n", (problem_check ? options_check : problem_check).error().describe().c_str());
    if (result)
      fail(input, "solveMultipleImpact solved a problem or options that validate() refuses");
    return 0;
  }
  if (result)
    checkResult(input, result.value());
  if (verbose)
  {
    const std::string outcome = result ? "solved, " + std::to_string(result.value().events.size()) + " events"
                                       : "refused: " + result.error().describe();
    std::fprintf(stderr, "%s\n", outcome.c_str());
  }
  return 0;
}
