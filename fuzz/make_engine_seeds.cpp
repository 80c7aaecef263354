// Writes the seed corpus of fuzz_impact_engine (engine_input.hpp's format) into the directory given: the paper's
// problems as the scenario builders make them, and a few small ones. Each seed is decoded again and compared with
// what was written, and solved. Run by hand after a change of the format:
//   build-asan/fuzz/make_engine_seeds fuzz/corpus/fuzz_impact_engine
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "../test/fixtures/paper_masse.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"
#include "engine_input.hpp"

namespace
{
using namespace billiard_shot_planner;
using fuzz_engine::EngineInputWriter;

struct Seed
{
  std::string name;
  ImpactProblem problem;
  SolverOptions options;  ///< only what EngineInputWriter::options can express
  int relative_choice = 0;
  int absolute_choice = 0;
  std::uint32_t max_events = 0;
};

bool same(const ImpactProblem& a, const ImpactProblem& b)
{
  if (a.mass_matrix != b.mass_matrix || a.velocity != b.velocity || a.contacts.size() != b.contacts.size())
    return false;
  for (std::size_t i = 0; i < a.contacts.size(); ++i)
  {
    const Contact& x = a.contacts[i];
    const Contact& y = b.contacts[i];
    const bool tangents = x.hasFriction() ? x.tangent == y.tangent : true;
    if (x.normal != y.normal || !tangents || x.law.restitution != y.law.restitution ||
        x.law.stiffness != y.law.stiffness || x.law.friction != y.law.friction || x.law.eta2 != y.law.eta2)
      return false;
  }
  return true;
}

ImpactProblem unwrap(Expected<ImpactProblem> problem, const char* name)
{
  if (!problem)
  {
    std::fprintf(stderr, "make_engine_seeds: %s: %s\n", name, problem.error().describe().c_str());
    std::exit(1);
  }
  return std::move(problem).value();
}

std::vector<Seed> seeds()
{
  std::vector<Seed> out;
  BallBallTable table1;  // paper Table 1
  table1.m2 = 1.1547;
  table1.e1 = 0.9;
  table1.e2 = 0.7;
  out.push_back({"ball_ball_table", unwrap(makeImpactProblem(table1), "ball_ball_table"), {}});

  BallChain cradle{{1, 1, 1}, {1, 0, 0}, {1, 1}, {1, 1}, false};
  out.push_back({"chain3", unwrap(makeImpactProblem(cradle), "chain3"), {}});
  BallChain wall{{1, 2, 1, 3}, {2, 1, 0, -0.5}, {1, 3, 1, 2}, {0.9, 0.5, 0, 1}, true};
  out.push_back({"chain4_wall_plastic", unwrap(makeImpactProblem(wall), "chain4_wall"), {}});

  out.push_back({"masse_on_axis", unwrap(makeImpactProblem(fixtures::paperMasseStrike()), "masse"), {}});
  CueStrike draw = fixtures::paperMasseStrike(Eigen::Vector3d(1, 0, 0));
  draw.cue_end_mass = TYPICAL_CUE_END_MASS;
  draw.hit_normal = Eigen::Vector3d(-0.9165, 0.2, -0.4).normalized();
  draw.cue_contact = {0.75, 0.7, 1.2};
  out.push_back({"draw_end_mass", unwrap(makeImpactProblem(draw), "draw"), {}});

  ImpactProblem landing = freeBallProblem(0.17, 0.0286, Eigen::Vector3d(0.5, 0.1, -1.0), Eigen::Vector3d(3, -20, 1));
  landing.contacts.push_back(makeContact("ball-table", clothContactRows(0.0286), ContactLaw{0.5, 1.0, 0.2, 10.0, {}}));
  out.push_back({"landing", landing, {}});

  ImpactProblem wall1;  // one body against a wall, e = 0.5
  wall1.mass_matrix = Eigen::MatrixXd::Constant(1, 1, 2.0);
  wall1.velocity = Eigen::VectorXd::Constant(1, -1.0);
  Contact c;
  c.name = "wall";
  c.normal = Eigen::RowVectorXd::Constant(1, 1.0);
  c.law.restitution = 0.5;
  wall1.contacts.push_back(c);
  out.push_back({"one_dof_wall", wall1, {}});

  Seed coarse{"masse_integrated_coarse", out[3].problem, {}, 1, 1, 0};  // 1e-6 both, every state integrated
  coarse.options.closed_form_linear_phases = false;
  coarse.options.separation_clock = false;
  out.push_back(coarse);
  Seed samples{"landing_samples", landing, {}};
  samples.options.record_samples = true;
  samples.options.quasi_steady_slip = false;
  out.push_back(samples);
  Seed few_events{"chain4_wall_20_events", out[2].problem, {}, 0, 0, 20};
  out.push_back(few_events);
  return out;
}
}  // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: make_engine_seeds DIRECTORY\n");
    return 2;
  }
  for (const Seed& seed : seeds())
  {
    EngineInputWriter writer;
    writer.problem(seed.problem);
    const SolverOptions& o = seed.options;
    writer.options(seed.relative_choice, seed.absolute_choice, o.closed_form_linear_phases, o.separation_clock,
                   o.quasi_steady_slip, o.record_samples, seed.max_events, 0);
    const std::vector<std::uint8_t> bytes = writer.bytes();

    FuzzedDataProvider in(bytes.data(), bytes.size());
    const fuzz_engine::EngineInput decoded = fuzz_engine::readEngineInput(in);
    if (!same(decoded.problem, seed.problem) || in.remaining_bytes() != 0 ||
        decoded.options.closed_form_linear_phases != o.closed_form_linear_phases ||
        decoded.options.record_samples != o.record_samples ||
        (seed.max_events != 0 && decoded.options.max_events != seed.max_events))
    {
      std::fprintf(stderr, "make_engine_seeds: %s does not decode to itself\n", seed.name.c_str());
      return 1;
    }
    const std::string path = std::string(argv[1]) + "/" + seed.name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    const auto solved = solveMultipleImpact(decoded.problem, decoded.options);
    std::printf("%s: %zu bytes, %zu dofs, %zu contacts: %s\n", path.c_str(), bytes.size(),
                static_cast<std::size_t>(seed.problem.velocity.size()), seed.problem.contacts.size(),
                solved ? ("solved, " + std::to_string(solved.value().events.size()) + " events").c_str()
                       : solved.error().describe().c_str());
  }
  return 0;
}
