// impact_report: solves the paper's ball–ball–table examples (Table 1 / Fig. 1, Fig. 7, Fig. 9) and prints, for
// each, the state sequence with impulses, velocities and energies at every state start, the contact events, the
// final velocities and the energy lost, beside the paper's printed values and the converged reference values
// (docs/validation.md, The paper's collisions); then the massé cue strike of §9.2 beside the paper's prediction and
// measurement (docs/validation.md, The massé shot).
#include <cmath>
#include <cstdio>
#include <exception>

#include "../fixtures/paper_masse.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
struct Example
{
  const char* title;
  bsp::BallBallTable collision;
  const char* printed;    // the paper's final velocities
  const char* converged;  // converged reference (docs/validation.md)
};

void printStates(const bsp::ImpactResult& r)
{
  std::printf("  %-5s %10s %10s %10s %10s %10s %10s %10s\n", "state", "I1", "I2", "v1", "v2", "E1", "E2", "total E");
  for (const bsp::ImpactState& state : r.states)
  {
    const bsp::ImpactSnapshot& s = state.start;
    std::printf("  %-5s %10.6f %10.6f %10.6f %10.6f %10.6f %10.6f %10.6f\n",
                bsp::ballBallTableStateName(state.active).c_str(), s.normal_impulses(0), s.normal_impulses(1),
                s.velocity(0), s.velocity(1), s.strain_energies(0), s.strain_energies(1), s.total_energy());
  }
}

void printEvents(const bsp::ImpactResult& r)
{
  const char* contact_names[] = {"ball-ball", "ball-table"};
  std::printf("  events:\n");
  for (const bsp::ContactEvent& e : r.events)
    std::printf("    %-22s %-10s at (I1, I2) = (%.6f, %.6f)\n", bsp::toString(e.type), contact_names[e.contact],
                e.at.normal_impulses(0), e.at.normal_impulses(1));
}

bool report(const Example& example)
{
  std::printf("\n%s\n", example.title);
  const bsp::BallBallTable& c = example.collision;
  std::printf("  m1 = %g, m2 = %.6f, k2/k1 = %g, e1 = %g, e2 = %g, v0 = %g\n", c.m1, c.m2, c.stiffness_ratio, c.e1,
              c.e2, c.v0);
  const auto result = bsp::solve(c);
  if (!result)
  {
    std::printf("  error: %s\n", result.error().describe().c_str());
    return false;
  }
  const bsp::ImpactResult& r = result.value();
  printStates(r);
  printEvents(r);
  std::printf("  final velocities   v1 = %.7f, v2 = %.7f%s\n", r.velocity(0), r.velocity(1),
              r.converged ? "  (limit of an infinite sequence)" : "");
  std::printf("  paper's printed    %s\n  converged reference %s\n", example.printed, example.converged);
  std::printf("  ends of compression: ball-ball %d, ball-table %d\n", r.ends_of_compression[0],
              r.ends_of_compression[1]);
  const double lost = r.initial_kinetic_energy - r.final_kinetic_energy;
  std::printf("  kinetic energy %.7f -> %.7f, lost %.7f (%.2f %%)\n", r.initial_kinetic_energy, r.final_kinetic_energy,
              lost, 100.0 * lost / r.initial_kinetic_energy);
  return true;
}
void printVector(const char* label, const Eigen::Vector3d& v)
{
  std::printf("  %-34s (%9.5f, %9.5f, %9.5f)\n", label, v.x(), v.y(), v.z());
}

/// The massé shot of §9.2 with the corrected mass and radius and the literal cue direction (docs/validation.md).
bool reportMasse()
{
  std::printf("\nThe massé shot of section 9.2 (m = 0.17 kg, r = 0.0286 m; corrections: docs/validation.md)\n");
  const auto result = bsp::solve(fixtures::paperMasseStrike());
  if (!result)
  {
    std::printf("  error: %s\n", result.error().describe().c_str());
    return false;
  }
  const bsp::CueStrikeResult& r = result.value();
  std::printf("  states:");
  for (const std::string& state : r.states)
    std::printf(" %s", state.c_str());
  std::printf("\n  events:\n");
  const char* names[] = {"cue-ball", "ball-table"};
  for (const bsp::ContactEvent& e : r.impact.events)
    std::printf("    %-22s %-10s at normal impulses (%.5f, %.5f) N s\n", bsp::toString(e.type), names[e.contact],
                e.at.normal_impulses(0), e.at.normal_impulses(1));
  printVector("ball velocity v (m/s)", r.velocity);
  printVector("ball angular velocity w (rad/s)", r.angular_velocity);
  printVector("paper's prediction (57): v", {-1.67629, -0.075349, 0.637937});
  printVector("paper's prediction (57): w", {40.3064, 83.6145, -15.4927});
  std::printf("  %-34s (%9.5f, %9.5f)  w_xy (%8.4f, %8.4f)\n", "measured (56): v_xy", -1.67063, -0.274431, 28.4584,
              79.1561);
  printVector("impulse on the cue (N s)", r.impulse_cue);
  printVector("impulse on the ball from the table", r.impulse_table);
  std::printf("  cue velocity after: %.5f m/s along its axis; miscue: %s\n", r.cue_velocity, r.miscue ? "yes" : "no");
  return true;
}
}  // namespace

int main()
try
{
  const double m2 = 2.0 / std::sqrt(3.0);
  const Example examples[] = {
      {"Table 1 / Fig. 1 and 8: collision with energy loss",
       {1.0, m2, 1.0, 0.9, 0.7, -1.0},
       "v1 = 0.61377, v2 = 0.20947",
       "v1 = 0.6139494, v2 = 0.2097195"},
      {"Fig. 7: elastic collision",
       {1.0, m2, 1.0, 1.0, 1.0, -1.0},
       "v1 = 0.94484, v2 = 0.30376",
       "v1 = 0.9451146, v2 = 0.3040649"},
      {"Fig. 9: restarts of compression (m2 = 0.5)",
       {1.0, 0.5, 1.0, 0.9, 0.7, -1.0},
       "(sequence printed as S1, S3, S4; see docs/validation.md, Fig. 7)",
       "v1 = 0.6368395, v2 = 0.1558096, S1, S2, S4"},
  };
  bool ok = true;
  for (const Example& example : examples)
    ok = report(example) && ok;
  ok = reportMasse() && ok;
  return ok ? 0 : 1;
}
catch (const std::exception& e)
{
  std::fprintf(stderr, "impact_report: %s\n", e.what());
  return 1;
}
