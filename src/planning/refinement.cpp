#include "refinement.hpp"

#include <nlopt.hpp>
#include <vector>

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// The first simplex's steps: a tenth of a degree of aim (the noise's order), a tenth of a m/s of speed.
constexpr double AIM_STEP = 0.1 * M_PI / 180.0, SPEED_STEP = 0.1;

struct Search
{
  const PlanContext& context;
  Clock::time_point deadline;
  RefinedShot best;

  StrokeEvaluation play(const Stroke& stroke)
  {
    ++best.evaluations;
    StrokeEvaluation evaluation = evaluateStroke(stroke, best.candidate.target, best.candidate.pocket, context);
    if (isBetter(evaluation, best.evaluation))
    {
      best.evaluation = evaluation;
      best.candidate.stroke = stroke;
    }
    return evaluation;
  }
};

double margin(const std::vector<double>& x, std::vector<double>& /*gradient*/, void* data)
{
  Search& search = *static_cast<Search*>(data);
  if (search.context.shouldStop(search.deadline))
    throw nlopt::forced_stop();
  Stroke stroke = search.best.candidate.stroke;
  stroke.phi = x[0];
  stroke.speed = x[1];
  return search.play(stroke).margin;
}
}  // namespace

double goodMargin(const Candidate& candidate, const PlanContext& context)
{
  return 0.5 * context.pockets[static_cast<std::size_t>(candidate.pocket)].radius;
}

RefinedShot refine(const Candidate& candidate, const PlanContext& context, Clock::time_point deadline)
{
  Search search{context, deadline, {candidate, {}, 0}};
  const double good_margin = goodMargin(candidate, context);
  search.best.evaluation.margin = UNPLAYABLE_MARGIN;
  if (search.play(candidate.stroke).margin >= good_margin)
    return search.best;
  const RobotLimits& limits = context.request.limits;
  nlopt::opt optimiser(nlopt::LN_SBPLX, 2);
  optimiser.set_lower_bounds({candidate.stroke.phi - MAX_AIM_CORRECTION, limits.min_speed});
  optimiser.set_upper_bounds({candidate.stroke.phi + MAX_AIM_CORRECTION, limits.max_speed});
  optimiser.set_initial_step({AIM_STEP, SPEED_STEP});
  optimiser.set_max_objective(margin, &search);
  optimiser.set_stopval(good_margin);
  optimiser.set_maxeval(MAX_EVALUATIONS - 1);
  optimiser.set_xtol_abs({1e-6, 1e-4});
  std::vector<double> x{candidate.stroke.phi, candidate.stroke.speed};
  double value = 0.0;
  try
  {
    optimiser.optimize(x, value);
  }
  catch (const std::exception&)  // forced stop at the deadline, or NLopt's round-off stop: keep the best so far
  {
  }
  return search.best;
}

}  // namespace planning
}  // namespace billiard_shot_planner
