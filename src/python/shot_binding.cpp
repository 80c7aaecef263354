#include "shot_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <optional>

#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/planning/stroke_conventions.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "layout.hpp"
#include "python_errors.hpp"
#include "shot_results.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
CuePlacement placed(const Stroke& stroke, const py::handle& cue_ball, const ShotConfiguration& configuration)
{
  return valueOf(placeStroke(stroke, point(cue_ball, "cue_ball"), configuration.ball_radius));
}

/// A cue given by its pose at the ball (tip and direction), at the cue ball `cue_ball`.
CuePlacement placed(CuePlacement cue, const py::handle& cue_ball, const ShotConfiguration& /*configuration*/)
{
  cue.ball = point(cue_ball, "cue_ball");
  return cue;
}

/// call()'s value (an Expected) computed with the GIL released, or its error raised in the names of a call with
/// the balls `others`.
template <class Call>
auto withoutGil(const Call& call, const std::vector<TableBall>& others)
{
  decltype(call()) result = Error{};
  {
    py::gil_scoped_release release;
    result = call();
  }
  if (!result)
    raise(inPythonTerms(result.error(), others));
  return std::move(result).value();
}

template <class Cue>
CueStrikeResult strike(const Cue& given, const py::object& cue_ball, const py::object& balls,
                       const ShotConfiguration& configuration)
{
  const CuePlacement cue = placed(given, cue_ball, configuration);
  const std::vector<TableBall> others = tableBalls(balls);
  return withoutGil([&] { return strikeBall(cue, configuration, others); }, others);
}

template <class Cue>
Shot predict(const Cue& given, const py::object& cue_ball, const py::object& balls,
             const ShotConfiguration& configuration)
{
  const CuePlacement cue = placed(given, cue_ball, configuration);
  const std::vector<TableBall> others = tableBalls(balls);
  return shotOf(withoutGil([&] { return predictShot(cue, configuration, others); }, others));
}

/// The path sampled: times (N,), positions (N, 3) and phases (N,) as numpy arrays.
py::tuple sample(const BallPath& path, double spacing)
{
  if (!(std::isfinite(spacing) && spacing > 0.0))
    raise(invalidArgument("spacing", "must be > 0 s"));
  const std::vector<TrajectorySample> samples = path.trajectory.sample(spacing);
  const auto n = static_cast<py::ssize_t>(samples.size());
  py::array_t<double> times(n);
  py::array_t<double> positions({n, py::ssize_t{3}});
  py::array_t<int> phases(n);
  auto t = times.mutable_unchecked<1>();
  auto p = positions.mutable_unchecked<2>();
  auto f = phases.mutable_unchecked<1>();
  for (py::ssize_t k = 0; k < n; ++k)
  {
    const TrajectorySample& s = samples[static_cast<std::size_t>(k)];
    t(k) = s.time;
    for (py::ssize_t j = 0; j < 3; ++j)
      p(k, j) = s.state.position(j);
    f(k) = static_cast<int>(s.phase);
  }
  return py::make_tuple(times, positions, phases);
}

void bindStroke(py::module_& module)
{
  py::class_<Stroke>(
      module, "Stroke",
      R"(A stroke in this package's convention (docs/stroke_conventions.md): phi, the cue's heading in the cloth
plane, rad counter-clockwise from +x of the table frame; theta, its elevation, rad; speed, the cue's, m/s; a and b,
the hit point right of and above the ball's centre as the player sees it, in ball radii (a > 0: right english).)")
      .def(py::init(
               [](double phi, double theta, double speed, double a, double b) {
                 return Stroke{phi, theta, speed, a, b};
               }),
           py::arg("phi") = 0.0, py::arg("theta") = 0.0, py::arg("speed") = 1.0, py::arg("a") = 0.0, py::arg("b") = 0.0)
      .def_readwrite("phi", &Stroke::phi)
      .def_readwrite("theta", &Stroke::theta)
      .def_readwrite("speed", &Stroke::speed)
      .def_readwrite("a", &Stroke::a)
      .def_readwrite("b", &Stroke::b)
      .def("__repr__",
           [](const Stroke& s)
           {
             return "Stroke(phi=" + std::to_string(s.phi) + ", theta=" + std::to_string(s.theta) +
                    ", speed=" + std::to_string(s.speed) + ", a=" + std::to_string(s.a) + ", b=" + std::to_string(s.b) +
                    ")";
           });
  module.def(
      "from_pooltool",
      [](double v0, double phi, double theta, double a, double b) {
        return fromPooltool({v0, phi, theta, a, b});
      },
      py::arg("V0"), py::arg("phi"), py::arg("theta") = 0.0, py::arg("a") = 0.0, py::arg("b") = 0.0,
      "pooltool's Cue (V0 m/s; phi, theta in degrees, phi from pooltool's +x across the table; a > 0 the ball's left) "
      "as a Stroke.");
  module.def(
      "to_pooltool",
      [](const Stroke& stroke)
      {
        const PooltoolStroke p = toPooltool(stroke);
        return py::make_tuple(p.V0, p.phi, p.theta, p.a, p.b);
      },
      py::arg("stroke"), "The Stroke as pooltool's (V0, phi, theta, a, b).");
  module.def(
      "from_fastfiz",
      [](double a, double b, double theta, double phi, double v, double ball_radius) {
        return fromFastFiz({a, b, theta, phi, v}, ball_radius);
      },
      py::arg("a"), py::arg("b"), py::arg("theta"), py::arg("phi"), py::arg("v"), py::arg("ball_radius") = 0.028575,
      "FastFiz's ShotParams(a, b, theta, phi, v) (a, b in mm, + right; degrees; phi from FastFiz's +x) as a Stroke.");
  module.def(
      "to_fastfiz",
      [](const Stroke& stroke, double ball_radius)
      {
        const FastFizShot f = toFastFiz(stroke, ball_radius);
        return py::make_tuple(f.a, f.b, f.theta, f.phi, f.v);
      },
      py::arg("stroke"), py::arg("ball_radius") = 0.028575, "The Stroke as FastFiz's (a, b, theta, phi, v).");
}

void bindCue(py::module_& module)
{
  py::class_<CuePlacement>(
      module, "Cue",
      R"(The cue by its pose at the moment it touches the ball (table frame): `tip`, the centre of its tip, on its
axis at or before the ball; `direction`, its direction of motion (normalised here); `speed`, m/s. The axis meets the
ball at the hit point. The alternative to a Stroke, for a cue a robot or a tracker gives as a pose.)")
      .def(py::init(
               [](const py::object& tip, const py::object& direction, double speed)
               {
                 CuePlacement cue;
                 cue.tip = vector3(tip, "tip");
                 cue.direction = vector3(direction, "direction");
                 cue.speed = speed;
                 return cue;
               }),
           py::arg("tip"), py::arg("direction"), py::arg("speed"))
      .def_readonly("tip", &CuePlacement::tip)
      .def_readonly("direction", &CuePlacement::direction)
      .def_readonly("speed", &CuePlacement::speed);
}

void bindResults(py::module_& module)
{
  py::class_<CueStrikeResult>(module, "Strike", "The cue ball right after the cue leaves it (table frame, SI units).")
      .def_readonly("velocity", &CueStrikeResult::velocity, "m/s")
      .def_readonly("angular_velocity", &CueStrikeResult::angular_velocity, "rad/s")
      .def_readonly("cue_velocity", &CueStrikeResult::cue_velocity, "m/s, the cue's along its axis after the shot")
      .def_readonly("hit_normal", &CueStrikeResult::hit_normal)
      .def_readonly("cue_direction", &CueStrikeResult::cue_direction)
      .def_readonly("states", &CueStrikeResult::states, "the contact states of the impact, S1 ... S4")
      .def_readonly("miscue", &CueStrikeResult::miscue)
      .def_readonly("leaves_cloth", &CueStrikeResult::leaves_cloth);
  py::class_<MotionEvent>(module, "Event", "An event of a ball's path: its type, time and the state after it.")
      .def_property_readonly("type", [](const MotionEvent& e) { return std::string(toString(e.type)); })
      .def_readonly("time", &MotionEvent::time)
      .def_property_readonly("position", [](const MotionEvent& e) { return e.state.position; })
      .def_property_readonly("velocity", [](const MotionEvent& e) { return e.state.velocity; })
      .def_property_readonly("angular_velocity", [](const MotionEvent& e) { return e.state.angular_velocity; })
      .def_readonly("cushion", &MotionEvent::cushion)
      .def_readonly("pocket", &MotionEvent::pocket)
      .def_readonly("ball", &MotionEvent::ball);
  py::class_<BallPath>(module, "BallPath", "One ball's path.")
      .def_readonly("id", &BallPath::id)
      .def_property_readonly("outcome", [](const BallPath& p) { return std::string(toString(p.trajectory.outcome)); })
      .def_property_readonly("pocket", [](const BallPath& p) { return p.trajectory.pocket(); })
      .def_property_readonly("final_position", [](const BallPath& p) { return p.trajectory.finalState().position; })
      .def_property_readonly("duration", [](const BallPath& p) { return p.trajectory.duration(); })
      .def_property_readonly("events", [](const BallPath& p) { return p.trajectory.events; })
      .def(
          "position_at", [](const BallPath& p, double t) { return p.trajectory.at(t).position; }, py::arg("time"))
      .def("sample", &sample, py::arg("spacing") = 0.01,
           "(times, positions, phases): numpy arrays of the path every `spacing` s and at every event; phases index "
           "PHASES.");
  py::class_<Shot>(module, "Shot", "A whole shot: the strike and every ball's path, the cue ball first.")
      .def_readonly("strike", &Shot::strike)
      .def_readonly("hit_point", &Shot::hit_point)
      .def_readonly("balls", &Shot::balls)
      .def_readonly("first_contact", &Shot::first_contact)
      .def(
          "ball",
          [](const Shot& shot, const std::string& id)
          {
            for (const BallPath& path : shot.balls)
              if (path.id == id)
                return path;
            raise(invalidArgument("id", "no ball '" + id + "' in this shot"));
          },
          py::arg("id"));
  module.attr("PHASES") = py::make_tuple("airborne", "sliding", "rolling", "spinning", "stationary");
}

template <class Cue>
void bindCalls(py::module_& module, const char* cue_name)
{
  module.def("strike", &strike<Cue>, py::arg(cue_name), py::arg("cue_ball") = py::make_tuple(0.0, 0.0),
             py::arg("balls") = py::none(), py::arg("configuration") = ShotConfiguration{},
             "The cue ball right after a Stroke or a Cue strikes it at `cue_ball` (x, y) on the cloth; `balls` (id -> "
             "(x, y)) touching it are struck in the same multiple impact. Raises Error.");
  module.def("predict_shot", &predict<Cue>, py::arg(cue_name), py::arg("cue_ball"), py::arg("balls") = py::none(),
             py::arg("configuration") = ShotConfiguration{},
             "The whole shot of a Stroke or a Cue: the strike, then every ball's path until all rest or drop. "
             "`cue_ball` (x, y) in m, `balls` a dict id -> (x, y) of the balls at rest. Raises Error.");
}
}  // namespace

void bindShots(py::module_& module)
{
  bindStroke(module);
  bindCue(module);
  bindResults(module);
  bindCalls<Stroke>(module, "stroke");
  bindCalls<CuePlacement>(module, "cue");
}

}  // namespace billiard_shot_planner::python
