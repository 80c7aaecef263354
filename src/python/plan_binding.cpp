#include "plan_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "layout.hpp"
#include "python_errors.hpp"
#include "shot_results.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// A plan as Python sees it: the core's, with its noise-free outcome as a Shot.
struct Plan
{
  ShotPlan plan;
  Shot shot;
};

/// What plan_shot() asks, beside the layout.
struct PlanOptions
{
  std::string target;
  std::string pocket;
  double budget = 0.5;
  unsigned seed = 1;
  int rollouts = 200;
  int threads = 0;
  ExecutionNoise noise;
  RobotLimits limits;
  bool target_first = false;
  bool only_target = false;
  py::object cue_region;
};

PlanRequest requestOf(const Layout& layout, const PlanOptions& options)
{
  PlanRequest request;
  TableBall cue{CUE_BALL_ID, {}};
  cue.state.position.head<2>() = layout.cue_ball;
  request.balls.push_back(cue);
  request.balls.insert(request.balls.end(), layout.balls.begin(), layout.balls.end());
  request.target = options.target;
  request.pocket = options.pocket;
  request.budget = options.budget;
  request.seed = options.seed;
  request.rollouts = options.rollouts;
  request.threads = options.threads;
  request.noise = options.noise;
  request.limits = options.limits;
  request.rules = {options.target_first, options.only_target};
  if (!options.cue_region.is_none())
  {
    py::tuple region;
    try
    {
      region = options.cue_region.cast<py::tuple>();
    }
    catch (const py::cast_error&)
    {
      raise(invalidArgument("cue_region", "must be ((x, y), radius) in m"));
    }
    if (region.size() != 2)
      raise(invalidArgument("cue_region", "must be ((x, y), radius) in m"));
    request.cue_region = CueRegion{point(region[0], "cue_region"), region[1].cast<double>()};
  }
  return request;
}

Plan plan(const py::handle& cue_ball, const py::object& balls, const ShotConfiguration& configuration,
          const PlanOptions& options)
{
  const PlanRequest request = requestOf(layoutOf(cue_ball, balls), options);
  check(validate(request, configuration));
  Expected<ShotPlan> planned = Error{};
  {
    py::gil_scoped_release release;
    planned = planShot(request, configuration);
  }
  ShotPlan shot_plan = valueOf(std::move(planned));
  Shot shot = shotOf(shot_plan.outcome);
  return {std::move(shot_plan), std::move(shot)};
}

py::array_t<double> endPoints(const PlannedShot& shot)
{
  py::array_t<double> points({static_cast<py::ssize_t>(shot.target_end_points.size()), py::ssize_t{2}});
  auto p = points.mutable_unchecked<2>();
  for (std::size_t i = 0; i < shot.target_end_points.size(); ++i)
  {
    p(static_cast<py::ssize_t>(i), 0) = shot.target_end_points[i].x();
    p(static_cast<py::ssize_t>(i), 1) = shot.target_end_points[i].y();
  }
  return points;
}

void bindSettings(py::module_& module)
{
  py::class_<ExecutionNoise>(module, "Noise",
                             R"(The robot's execution noise: one standard deviation per stroke parameter (phi,
theta in rad; speed in m/s; a, b in m of the hit point). Defaults: FastFiz's level 1.)")
      .def(py::init<>())
      .def_readwrite("phi", &ExecutionNoise::phi)
      .def_readwrite("theta", &ExecutionNoise::theta)
      .def_readwrite("speed", &ExecutionNoise::speed)
      .def_readwrite("a", &ExecutionNoise::a)
      .def_readwrite("b", &ExecutionNoise::b);
  py::class_<RobotLimits>(module, "Limits",
                          "What the robot can do: the cue's elevation and speed ranges (rad, m/s), "
                          "the largest tip offset (radii), the cue that must clear balls and rails.")
      .def(py::init<>())
      .def_readwrite("min_theta", &RobotLimits::min_theta)
      .def_readwrite("max_theta", &RobotLimits::max_theta)
      .def_readwrite("min_speed", &RobotLimits::min_speed)
      .def_readwrite("max_speed", &RobotLimits::max_speed)
      .def_readwrite("max_offset", &RobotLimits::max_offset)
      .def_readwrite("cue_length", &RobotLimits::cue_length)
      .def_readwrite("cue_radius", &RobotLimits::cue_radius)
      .def_readwrite("rail_height", &RobotLimits::rail_height);
}

void bindResults(py::module_& module)
{
  py::class_<PlannedShot>(module, "PlannedShot", "A shot and how likely it is to pot under the noise.")
      .def_readonly("stroke", &PlannedShot::stroke)
      .def_readonly("cue", &PlannedShot::cue)
      .def_readonly("target", &PlannedShot::target)
      .def_readonly("pocket", &PlannedShot::pocket, "the pocket's id (\"top_right\")")
      .def_readonly("bank_cushion", &PlannedShot::bank_cushion, "the rail's id (\"rail.top\"); \"\": straight in")
      .def_property_readonly("cue_ball_path",
                             [](const PlannedShot& s) { return std::string(toString(s.cue_ball_path)); })
      .def_readonly("margin", &PlannedShot::margin, "m inside the pocket's capture circle, noise-free")
      .def_readonly("success_probability", &PlannedShot::success_probability)
      .def_property_readonly("confidence",
                             [](const PlannedShot& s) { return py::make_tuple(s.confidence_low, s.confidence_high); })
      .def_readonly("rollouts", &PlannedShot::rollouts)
      .def_property_readonly("target_end_points", &endPoints, "(N, 2): where the target ended in each rollout");
  py::class_<Plan>(module, "Plan", "The planner's answer.")
      .def_property_readonly("found", [](const Plan& p) { return p.plan.found; })
      .def_property_readonly("best", [](const Plan& p) { return p.plan.best; })
      .def_property_readonly("explanation", [](const Plan& p) { return p.plan.explanation; })
      .def_readonly("shot", &Plan::shot, "the noise-free shot of `best`")
      .def_property_readonly("alternatives", [](const Plan& p) { return p.plan.alternatives; })
      .def_property_readonly("evaluations", [](const Plan& p) { return p.plan.evaluations; })
      .def_property_readonly("seconds", [](const Plan& p) { return p.plan.seconds; });
}
}  // namespace

void bindPlanning(py::module_& module)
{
  bindSettings(module);
  bindResults(module);
  module.def(
      "plan_shot",
      [](const py::handle& cue_ball, const py::object& balls, const std::string& target, const std::string& pocket,
         double budget, unsigned seed, int rollouts, int threads, const ExecutionNoise& noise,
         const RobotLimits& limits, bool target_first, bool only_target, const py::object& cue_region,
         const ShotConfiguration& configuration)
      {
        const PlanOptions options{target, pocket, budget,       seed,        rollouts,  threads,
                                  noise,  limits, target_first, only_target, cue_region};
        return plan(cue_ball, balls, configuration, options);
      },
      py::arg("cue_ball"), py::arg("balls"), py::arg("target") = "", py::arg("pocket") = "", py::arg("budget") = 0.5,
      py::arg("seed") = 1, py::arg("rollouts") = 200, py::arg("threads") = 0, py::arg("noise") = ExecutionNoise{},
      py::arg("limits") = RobotLimits{}, py::arg("target_first") = false, py::arg("only_target") = false,
      py::arg("cue_region") = py::none(), py::arg("configuration") = ShotConfiguration{},
      R"(The stroke that pots `target` (any object ball when empty) in `pocket` (a pocket's id, "top_right";
"": any) from the cue ball at `cue_ball` among `balls` (id -> (x, y)), and how likely it is under `noise`
(docs/planning.md): within `budget` s of wall-clock time, `rollouts` noisy rollouts per shot that pots on `threads`
threads, reproducible for a seed. Options: the rules `target_first`, `only_target`; `cue_region` ((x, y), r) where the
cue ball must stop. Raises Error.)");
}

}  // namespace billiard_shot_planner::python
