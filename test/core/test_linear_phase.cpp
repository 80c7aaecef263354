// The closed-form propagation of linear states (src/impact/linear_phase.cpp) against numerical integration of the
// same spring dynamics (Bulirsch–Stoer at tolerance 1e-13): the same state sequence and the same final velocities
// to 1e-9, on frictionless collisions, rigid links (e = 0), pure stick, sliding with a fixed direction (landings),
// and cases whose sliding direction turns (massé strike, cushion hits), which must be left to the integrator, as
// must a phase with a loaded spring whose law is not linear.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../../src/impact/contact_dynamics.hpp"
#include "../../src/impact/contact_space.hpp"
#include "../../src/impact/linear_phase.hpp"
#include "../../src/impact/state_transitions.hpp"
#include "../fixtures/paper_masse.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"
#include "same_solution.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
bsp::SolverOptions numerical()
{
  return same_solution::integratedOnly(1e-13);
}

template <class Problem>
void expectSameSolution(const Problem& problem, const char* name)
{
  same_solution::expectSameSolution(problem, bsp::SolverOptions{}, numerical(), 1e-9, name);
}
}  // namespace

TEST(LinearPhase, FrictionlessCollisionsMatchNumericalIntegration)
{
  const double m2 = 2.0 / std::sqrt(3.0);
  expectSameSolution(bsp::BallBallTable{1.0, m2, 1.0, 0.9, 0.7, -1.0}, "Table 1");
  expectSameSolution(bsp::BallBallTable{1.0, m2, 1.0, 1.0, 1.0, -1.0}, "Fig. 7");
  expectSameSolution(bsp::BallBallTable{1.0, 0.5, 1.0, 0.9, 0.7, -1.0}, "Fig. 9");
  expectSameSolution(bsp::BallBallTable{1.0, 1.0, 2.25, 0.950043, 0.846529, -1.0}, "ping-pong");
  bsp::BallChain chain;
  chain.masses = {1.0, 2.0, 0.5, 1.0, 3.0};
  chain.velocities = {1.0, 0.0, 0.0, 0.0, -0.2};
  chain.stiffness = {1.0, 3.0, 0.5, 2.0};
  chain.restitution = {1.0, 0.8, 0.6, 0.9};
  expectSameSolution(chain, "uneven chain");
  // States of two moving springs take their modes from one Jacobi rotation: its edge cases, equal diagonal terms
  // (a rotation by 45°) and two contacts that share no ball (no coupling: no rotation at all).
  bsp::BallChain three;
  three.masses = {1.0, 1.0, 1.0};
  three.velocities = {1.0, 0.0, 0.0};
  three.stiffness = {1.0, 1.0};
  three.restitution = {1.0, 1.0};
  expectSameSolution(three, "three equal balls");
  bsp::BallChain pairs;
  pairs.masses = {1.0, 2.0, 1.0, 0.5};
  pairs.velocities = {1.0, 0.0, 0.5, -0.5};  // balls 1 and 2 part: two collisions at once, uncoupled at first
  pairs.stiffness = {1.0, 1.0, 2.0};
  pairs.restitution = {0.9, 1.0, 0.7};
  expectSameSolution(pairs, "two pairs at once");
}

TEST(LinearPhase, RigidLinksMatchNumericalIntegration)
{
  bsp::BallChain chain;  // e = 0 at the wall: a rigid link while the balls behind still push
  chain.masses = {1.0, 1.0, 1.0};
  chain.velocities = {1.0, 0.5, 0.0};
  chain.stiffness = {1.0, 1.0, 1.0};
  chain.restitution = {0.9, 0.8, 0.0};
  chain.wall = true;
  expectSameSolution(chain, "chain against a plastic wall");
  const auto r = bsp::solve(chain).value();
  const auto links =
      std::count_if(r.events.begin(), r.events.end(),
                    [](const bsp::ContactEvent& event) { return event.type == bsp::ContactEventType::RigidLink; });
  EXPECT_GT(links, 0);  // the case exercises the rigid-link projection
}

TEST(LinearPhase, StickingContactsMatchNumericalIntegration)
{
  bsp::BallTableImpact impact;  // μ → ∞: sticks throughout, only the closed form runs
  impact.velocity = {0.3, 0.0, -1.0};
  impact.table = {0.6, 1e9, 7.0};
  expectSameSolution(impact, "pure stick");
  impact.velocity = {0.3, -0.2, -1.0};  // docs/validation.md, One compliant contact, case E: stick, then slip
  impact.angular_velocity = {1.5, 0.4, 0.0};
  impact.table = {0.5, 0.25, 7.0};
  expectSameSolution(impact, "stick then slip");
  expectSameSolution(fixtures::paperMasseStrike(), "massé strike");
}

TEST(LinearPhase, SlidingWithAFixedDirectionMatchesNumericalIntegration)
{
  // A ball alone on the table: friction only changes the tangential velocity along itself, so a contact that
  // slides from the first instant keeps its direction and the state is linear.
  bsp::BallTableImpact landing;
  landing.mass = 0.17;
  landing.radius = 0.0286;
  landing.velocity = {-2.07, 0.24, -0.4};
  landing.angular_velocity = {11.6, 25.3, -6.15};
  landing.table = {0.51625, 0.152479, 10.0};
  expectSameSolution(landing, "sliding landing");
  landing.velocity = {2.9, 0.5, -1.5};  // slides, sticks, slides again (then in a direction that may turn)
  landing.angular_velocity = {0.0, 0.0, 0.0};
  landing.table = {0.5, 0.6, 3.0};
  expectSameSolution(landing, "slide, stick, slide");
}

TEST(LinearPhase, TurningSlidingDirectionsAreLeftToTheIntegrator)
{
  bsp::CushionImpact cushion;  // cushion and cloth at once, with spin: both contacts slide, their directions turn
  cushion.velocity = {1.5, 0.8, 0.0};
  cushion.angular_velocity = {-10.0, 30.0, 20.0};
  cushion.cushion_normal = -Eigen::Vector3d::UnitX();
  cushion.cushion = {0.85, 0.2, 10.0};
  cushion.cloth = {0.51625, 0.152479, 10.0};
  expectSameSolution(cushion, "cushion hit on the cloth");
  cushion.on_cloth = false;
  cushion.velocity.z() = -0.3;
  expectSameSolution(cushion, "cushion hit in flight");
}

TEST(LinearPhase, APhaseWithASpringThatIsNotLinearIsLeftToTheIntegrator)
{
  // Two free bodies pressed by one frictionless contact: a linear phase, unless its spring says it is not linear.
  bsp::ImpactProblem problem;
  problem.mass_matrix = Eigen::Matrix2d::Identity();
  problem.velocity = Eigen::Vector2d(1.0, 0.0);
  bsp::Contact contact;
  contact.normal = Eigen::Vector2d(-1.0, 1.0);
  problem.contacts.push_back(contact);
  const bsp::detail::ContactSpace space = bsp::detail::buildContactSpace(problem);
  std::vector<bsp::detail::ContactState> states = bsp::detail::initialContactStates(problem, space);
  states[0].phase = bsp::detail::NormalPhase::Compression;
  bsp::detail::ContactDynamics dynamics(space, states, 1.0);
  const bsp::detail::OdeState y0{0.0, -0.1};  // an impulse, a pressed spring
  bsp::detail::LinearPhaseStepper stepper;
  EXPECT_TRUE(states[0].normal.linear);
  EXPECT_TRUE(stepper.build(space, states, dynamics, y0, 0.0, 0.1));
  states[0].normal.linear = false;
  dynamics.refresh();
  EXPECT_FALSE(stepper.build(space, states, dynamics, y0, 0.0, 0.1));
  states[0].phase = bsp::detail::NormalPhase::Inactive;  // unloaded, its law does not enter the phase
  dynamics.refresh();
  EXPECT_TRUE(stepper.build(space, states, dynamics, y0, 0.0, 0.1));
}

TEST(LinearPhase, ContactsNotReachedYetDoNotSwitchOnRoundOff)
{
  // The last five balls touch at rest: their contacts start in compression at v_n = 0, and until the collision reaches
  // them their velocities are sums of cancelling modes, zero to round-off. The closed form's crossing search once
  // read that round-off as a rise through zero: an end and a restart of compression at the far end at the first
  // event, and final velocities off by 0.009. (A random chain: its round-off pattern needs every digit.)
  bsp::BallChain chain;
  chain.masses = {0.83592576009963371, 1.8794591996081538, 1.8460783761356143, 1.4442949620754957,
                  0.71553130595111081, 0.2362291842441776, 2.1218315093086231};
  chain.velocities = {1, -0.39844230897340244, 0, 0, 0, 0, 0};
  chain.stiffness = {1.1600730969875874, 3.0936528516323571, 0.22781271395227692,
                     1.3370482682604774, 1.2811614048175659, 1.1350394897597016};
  chain.restitution = {0.60116950166841565, 0.7859328589737189,  0.58782837365867158,
                       0.72476840053096581, 0.96118825765025384, 0.90983651187093173};
  expectSameSolution(chain, "chain touching at rest");
}
