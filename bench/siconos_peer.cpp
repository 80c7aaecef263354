// Side by side with the peer: Siconos's LZB multiple-impact model (MultipleImpact, "BiStiffness" law) and this
// package on the same elastic problems, in one run (Google Benchmark). Run by ./scripts/bench; not part of the tests.
//
// Problems: the elastic ball–ball–table collision of the paper's Fig. 7 (m1 = 1, m2 = 2/√3, k2/k1 = 1, e = 1,
// v0 = −1) and a 10-ball elastic chain (unit masses, linear unit stiffness, the first ball at 1 m/s). With every
// contact elastic the LZB model coincides with the paper's; with e < 1 it would not, because BiStiffness resets a
// contact's stiffness when it touches again after separating (the paper keeps k/e^{2j}, assumption iii of §3.3).
//
// Siconos is driven through its own event-driven simulation (LsodarOSI, impact problem MultipleImpact) from the
// instant of contact; only its MultipleImpact::compute is timed. Errors are the largest difference of the final
// velocities from a converged solution (bench_problems.hpp), which agrees with the independent converged values of
// docs/validation.md (Fig. 7) and with the limit of Siconos's first-order sequence.
#include <benchmark/benchmark.h>
#include <SiconosKernel.hpp>

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bench_support.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// MultipleImpact with its solve timed: compute() is what the event-driven simulation calls at the impact.
class TimedMultipleImpact : public MultipleImpact
{
public:
  TimedMultipleImpact(double impulse_step) : MultipleImpact("BiStiffness", impulse_step) {}

  int compute(double time) override
  {
    const auto start = std::chrono::steady_clock::now();
    const int status = MultipleImpact::compute(time);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++calls;
    return status;
  }

  double seconds = 0.0;
  int calls = 0;
};

/// One-dimensional bodies along a line; every contact linear (force k·δ) and elastic.
class SiconosLine
{
public:
  SP::LagrangianLinearTIDS addBody(double mass, double position, double velocity)
  {
    auto mass_matrix = std::make_shared<SimpleMatrix>(1, 1);
    (*mass_matrix)(0, 0) = mass;
    auto q0 = std::make_shared<SiconosVector>(1);
    (*q0)(0) = position;
    auto v0 = std::make_shared<SiconosVector>(1);
    (*v0)(0) = velocity;
    bodies_.push_back(std::make_shared<LagrangianLinearTIDS>(q0, v0, mass_matrix));
    system_->insertDynamicalSystem(bodies_.back());
    return bodies_.back();
  }

  /// Gap y = q_ahead − q_behind − distance between two bodies.
  void contact(const SP::LagrangianLinearTIDS& behind, const SP::LagrangianLinearTIDS& ahead, double distance,
               double stiffness)
  {
    auto h = std::make_shared<SimpleMatrix>(1, 2);
    (*h)(0, 0) = -1.0;
    (*h)(0, 1) = 1.0;
    system_->link(makeInteraction(h, distance, stiffness), behind, ahead);
  }

  /// Gap y = q − distance to a fixed floor at 0.
  void floorContact(const SP::LagrangianLinearTIDS& body, double distance, double stiffness)
  {
    auto h = std::make_shared<SimpleMatrix>(1, 1);
    (*h)(0, 0) = 1.0;
    system_->link(makeInteraction(h, distance, stiffness), body);
  }

  /// Runs the simulation to its first impact; returns the time spent in MultipleImpact::compute.
  double solveImpact(double impulse_step)
  {
    auto impact = std::make_shared<TimedMultipleImpact>(impulse_step);
    impact->SetNstepMax(2000000000u);  // the default 100 000 ends small steps early
    auto simulation = std::make_shared<EventDriven>(system_, std::make_shared<TimeDiscretisation>(0.0, 0.5));
    simulation->insertIntegrator(std::make_shared<LsodarOSI>());
    simulation->insertNonSmoothProblem(impact, SICONOS_OSNSP_ED_IMPACT);
    simulation->insertNonSmoothProblem(std::make_shared<LCP>(), SICONOS_OSNSP_ED_SMOOTH_ACC);
    simulation->initialize();
    for (int event = 0; impact->calls == 0 && simulation->hasNextEvent(); ++event)
    {
      if (event > 10)
        throw std::runtime_error("Siconos found no impact");
      simulation->advanceToEvent();
      simulation->processEvents();
    }
    return impact->seconds;
  }

  Eigen::VectorXd velocities() const
  {
    Eigen::VectorXd v(static_cast<Eigen::Index>(bodies_.size()));
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      v(static_cast<Eigen::Index>(i)) = (*bodies_[i]->velocity())(0);
    return v;
  }

private:
  static SP::Interaction makeInteraction(const SP::SimpleMatrix& h, double distance, double stiffness)
  {
    auto offset = std::make_shared<SiconosVector>(1);
    (*offset)(0) = -distance;
    constexpr double restitution = 1.0, linear = 1.0;
    return std::make_shared<Interaction>(std::make_shared<MultipleImpactNSL>(restitution, stiffness, linear),
                                         std::make_shared<LagrangianLinearTIR>(h, offset));
  }

  SP::NonSmoothDynamicalSystem system_ = std::make_shared<NonSmoothDynamicalSystem>(0.0, 1.0);
  std::vector<SP::LagrangianLinearTIDS> bodies_;
};

/// Fig. 7 at the instant of contact (radius 0.5: positions exact in binary). Velocities ordered (v1, v2).
SiconosLine siconosFigure7()
{
  const bsp::BallBallTable c = bench::figure7();
  SiconosLine line;
  const auto lower = line.addBody(c.m2, 0.5, 0.0);
  const auto upper = line.addBody(c.m1, 1.5, c.v0);
  line.floorContact(lower, 0.5, c.stiffness_ratio);
  line.contact(lower, upper, 1.0, 1.0);
  return line;
}

SiconosLine siconosChain()
{
  const bsp::BallChain c = bench::elasticChain(10);
  SiconosLine line;
  std::vector<SP::LagrangianLinearTIDS> balls;
  for (std::size_t i = 0; i < c.masses.size(); ++i)
    balls.push_back(line.addBody(c.masses[i], static_cast<double>(i), c.velocities[i]));
  for (std::size_t i = 0; i + 1 < balls.size(); ++i)
    line.contact(balls[i], balls[i + 1], 1.0, c.stiffness[i]);
  return line;
}

/// Siconos orders Fig. 7's bodies (lower, upper); the package reports (v1, v2) = (upper, lower).
Eigen::VectorXd inPackageOrder(const Eigen::VectorXd& v, bool figure)
{
  if (!figure)
    return v;
  return Eigen::Vector2d(v(1), v(0));
}

template <class Problem>
void siconosSolve(benchmark::State& state, const Problem& problem, SiconosLine (*build)(), bool figure)
{
  const double step = std::pow(10.0, -static_cast<double>(state.range(0)));
  Eigen::VectorXd velocities;
  for (auto _ : state)
  {
    SiconosLine line = build();
    state.SetIterationTime(line.solveImpact(step));
    velocities = inPackageOrder(line.velocities(), figure);
  }
  state.counters["velocity_error"] = (velocities - bench::referenceVelocities(problem)).cwiseAbs().maxCoeff();
}

/// Argument: −log10 of the relative tolerance; negative: the default closed form, else numerical integration alone.
template <class Problem>
void packageSolve(benchmark::State& state, const Problem& problem)
{
  bench::timeSolves(state, problem,
                    state.range(0) < 0 ? bsp::SolverOptions{}
                                       : bench::integratedOnly(std::pow(10.0, -static_cast<double>(state.range(0)))));
}

void BM_SiconosFigure7(benchmark::State& state)
{
  siconosSolve(state, bench::figure7(), siconosFigure7, true);
}

void BM_SiconosChain10(benchmark::State& state)
{
  siconosSolve(state, bench::elasticChain(10), siconosChain, false);
}

void BM_PackageFigure7(benchmark::State& state)
{
  packageSolve(state, bench::figure7());
}

void BM_PackageChain10(benchmark::State& state)
{
  packageSolve(state, bench::elasticChain(10));
}

/// Steps 1e-2 … 1e-6: the cost grows as 1/step, so the small steps run once per repetition.
void siconosSteps(benchmark::internal::Benchmark* b)
{
  b->UseManualTime()->Unit(benchmark::kMicrosecond);
  for (int exponent = 2; exponent <= 6; ++exponent)
    b->Arg(exponent);
  b->Iterations(1)->Repetitions(3);  // 1e-6 takes seconds a solve
}
}  // namespace

BENCHMARK(BM_SiconosFigure7)->Apply(siconosSteps);
BENCHMARK(BM_SiconosChain10)->Apply(siconosSteps);
// Argument: −1 the package's default (closed form); 8 and 13: numerical integration alone at that tolerance.
BENCHMARK(BM_PackageFigure7)->Arg(-1)->Arg(8)->Arg(13)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PackageChain10)->Arg(-1)->Arg(8)->Arg(13)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
