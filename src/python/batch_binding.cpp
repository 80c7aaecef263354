#include "batch_binding.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "layout.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
constexpr std::size_t MAX_BATCH = 10'000'000;
constexpr int MAX_THREADS = 256;

/// The strokes of a batch: an (N, 5) array of phi, theta, speed, a, b (this package's convention).
std::vector<Stroke> strokesOf(const py::handle& given)
{
  const char* const what = "must be an (N, 5) array of phi, theta, speed, a, b";
  const py::array_t<double> array = arrayOf(given, 2, "strokes", what);
  if (array.shape(1) != 5)
    raise(invalidArgument("strokes", what));
  if (static_cast<std::size_t>(array.shape(0)) > MAX_BATCH)
    raise(invalidArgument("strokes", "at most " + std::to_string(MAX_BATCH) + " rows"));
  const auto rows = array.unchecked<2>();
  std::vector<Stroke> strokes;
  strokes.reserve(static_cast<std::size_t>(rows.shape(0)));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i)
    strokes.push_back({rows(i, 0), rows(i, 1), rows(i, 2), rows(i, 3), rows(i, 4)});
  return strokes;
}

int threadCount(int threads, std::size_t rows)
{
  if (threads < 0 || threads > MAX_THREADS)
    raise(invalidArgument("threads", "must be in [0, " + std::to_string(MAX_THREADS) + "] (0: one per core)"));
  const int cores = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(cores), std::max<std::size_t>(rows, 1)));
}

/// work(i) for every row i on `threads` threads, rows handed out one at a time (shots differ much in cost).
template <class Work>
void forEachRow(std::size_t rows, int threads, const Work& work)
{
  std::atomic<std::size_t> next{0};
  auto run = [&]
  {
    for (std::size_t i = next++; i < rows; i = next++)
      work(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(run);
  run();
  for (std::thread& thread : pool)
    thread.join();
}

/// A row's answer: the cue ball after the strike and every ball's end, or the row's error.
struct RowOutcome
{
  std::optional<Error> error;
  Eigen::Vector3d velocity = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  std::vector<Eigen::Vector3d> final_positions;
  std::vector<std::string> pockets;  ///< each ball's pocket id, empty when it did not drop
};

/// A row's stroke placed at the cue ball and `solve`d there; either's error in the Python call's names.
template <class Solve>
auto solvedRow(const Stroke& stroke, const Layout& layout, const ShotConfiguration& configuration, const Solve& solve)
    -> decltype(solve(CuePlacement{}))
{
  auto cue = placeStroke(stroke, layout.cue_ball, configuration.ball_radius);
  if (!cue)
    return cue.error();
  auto solved = solve(cue.value());
  if (!solved)
    return inPythonTerms(solved.error(), layout.balls);
  return solved;
}

RowOutcome simulateRow(const Stroke& stroke, const Layout& layout, const ShotConfiguration& configuration)
{
  RowOutcome row;
  const auto shot = solvedRow(stroke, layout, configuration,
                              [&](const CuePlacement& cue) { return predictShot(cue, configuration, layout.balls); });
  if (!shot)
  {
    row.error = shot.error();
    return row;
  }
  row.velocity = shot.value().strike.velocity;
  row.angular_velocity = shot.value().strike.angular_velocity;
  for (const BallTrajectory& ball : shot.value().table.balls)
  {
    row.final_positions.push_back(ball.finalState().position);
    row.pockets.push_back(ball.pocket());
  }
  return row;
}

py::object errorsOf(const std::vector<RowOutcome>& rows)
{
  py::list errors;
  for (const RowOutcome& row : rows)
    errors.append(row.error ? errorObject(*row.error) : py::none());
  return std::move(errors);
}

/// A row's strike: the cue ball's velocities, each other ball's (zero where the strike did not move it), the flags.
struct StrikeRow
{
  std::optional<Error> error;
  CueStrikeResult strike;
};

StrikeRow strikeRow(const Stroke& stroke, const Layout& layout, const ShotConfiguration& configuration)
{
  StrikeRow row;
  auto struck = solvedRow(stroke, layout, configuration,
                          [&](const CuePlacement& cue) { return strikeBall(cue, configuration, layout.balls); });
  if (!struck)
    row.error = struck.error();
  else
    row.strike = std::move(struck).value();
  return row;
}

/// Row i's vector in (N, 3) rows, NaN for a row that failed.
void putRow(py::detail::unchecked_mutable_reference<double, 2>& out, py::ssize_t i, const Eigen::Vector3d& value,
            bool known)
{
  for (py::ssize_t j = 0; j < 3; ++j)
    out(i, j) = known ? value(j) : std::numeric_limits<double>::quiet_NaN();
}

py::dict strikeMany(const py::handle& strokes_given, const py::handle& cue_ball, const py::object& balls,
                    const ShotConfiguration& configuration, int threads)
{
  const std::vector<Stroke> strokes = strokesOf(strokes_given);
  const Layout layout = layoutOf(cue_ball, balls);
  const int workers = threadCount(threads, strokes.size());
  std::vector<StrikeRow> rows(strokes.size());
  {
    py::gil_scoped_release release;
    forEachRow(strokes.size(), workers, [&](std::size_t i) { rows[i] = strikeRow(strokes[i], layout, configuration); });
  }
  const auto n = static_cast<py::ssize_t>(rows.size());
  const auto others = static_cast<py::ssize_t>(layout.balls.size());
  py::array_t<double> velocity({n, py::ssize_t{3}}), angular_velocity({n, py::ssize_t{3}});
  py::array_t<double> other_velocity({n, others, py::ssize_t{3}}), other_angular_velocity({n, others, py::ssize_t{3}});
  py::array_t<bool> miscue(n), leaves_cloth(n);
  auto v = velocity.mutable_unchecked<2>();
  auto w = angular_velocity.mutable_unchecked<2>();
  auto ov = other_velocity.mutable_unchecked<3>();
  auto ow = other_angular_velocity.mutable_unchecked<3>();
  auto m = miscue.mutable_unchecked<1>();
  auto l = leaves_cloth.mutable_unchecked<1>();
  py::list errors;
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const StrikeRow& row = rows[static_cast<std::size_t>(i)];
    const bool known = !row.error;
    putRow(v, i, row.strike.velocity, known);
    putRow(w, i, row.strike.angular_velocity, known);
    for (py::ssize_t k = 0; k < others; ++k)
      for (py::ssize_t j = 0; j < 3; ++j)
        ov(i, k, j) = ow(i, k, j) = known ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    for (const StruckBall& moved : row.strike.other_balls)  // numbered from 1: 0 is the cue ball
      for (py::ssize_t j = 0; moved.ball >= 1 && moved.ball <= layout.balls.size() && j < 3; ++j)
      {
        ov(i, static_cast<py::ssize_t>(moved.ball) - 1, j) = moved.velocity(j);
        ow(i, static_cast<py::ssize_t>(moved.ball) - 1, j) = moved.angular_velocity(j);
      }
    m(i) = known && row.strike.miscue;
    l(i) = known && row.strike.leaves_cloth;
    errors.append(row.error ? errorObject(*row.error) : py::none());
  }
  py::dict answer;
  answer["ids"] = layout.ids();
  answer["velocity"] = velocity;
  answer["angular_velocity"] = angular_velocity;
  answer["other_velocity"] = other_velocity;
  answer["other_angular_velocity"] = other_angular_velocity;
  answer["miscue"] = miscue;
  answer["leaves_cloth"] = leaves_cloth;
  answer["error"] = errors;
  return answer;
}

py::dict simulateMany(const py::handle& strokes_given, const py::handle& cue_ball, const py::object& balls,
                      const ShotConfiguration& configuration, int threads)
{
  const std::vector<Stroke> strokes = strokesOf(strokes_given);
  const Layout layout = layoutOf(cue_ball, balls);
  const int workers = threadCount(threads, strokes.size());
  std::vector<RowOutcome> rows(strokes.size());
  {
    py::gil_scoped_release release;
    forEachRow(strokes.size(), workers,
               [&](std::size_t i) { rows[i] = simulateRow(strokes[i], layout, configuration); });
  }
  const auto n = static_cast<py::ssize_t>(rows.size());
  const auto b = static_cast<py::ssize_t>(layout.balls.size() + 1);
  py::array_t<double> velocity({n, py::ssize_t{3}});
  py::array_t<double> angular_velocity({n, py::ssize_t{3}});
  py::array_t<double> final_position({n, b, py::ssize_t{3}});
  py::list pocket;
  auto v = velocity.mutable_unchecked<2>();
  auto w = angular_velocity.mutable_unchecked<2>();
  auto f = final_position.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const RowOutcome& row = rows[static_cast<std::size_t>(i)];
    for (py::ssize_t j = 0; j < 3; ++j)
    {
      v(i, j) = row.velocity(j);
      w(i, j) = row.angular_velocity(j);
    }
    py::list pockets;
    for (py::ssize_t k = 0; k < b; ++k)
    {
      const bool known = !row.error && static_cast<std::size_t>(k) < row.final_positions.size();
      for (py::ssize_t j = 0; j < 3; ++j)
        f(i, k, j) =
            known ? row.final_positions[static_cast<std::size_t>(k)](j) : std::numeric_limits<double>::quiet_NaN();
      pockets.append(known ? row.pockets[static_cast<std::size_t>(k)] : std::string());
    }
    pocket.append(pockets);
  }
  py::dict answer;
  answer["ids"] = layout.ids();
  answer["velocity"] = velocity;
  answer["angular_velocity"] = angular_velocity;
  answer["final_position"] = final_position;
  // A string array (numpy's "<U"): compares element by element with a pocket's id.
  answer["pocket"] = py::module_::import("numpy").attr("array")(pocket, py::arg("dtype") = "str");
  answer["error"] = errorsOf(rows);
  return answer;
}
}  // namespace

void bindBatches(py::module_& module)
{
  module.def("simulate_many", &simulateMany, py::arg("strokes"), py::arg("cue_ball"), py::arg("balls") = py::none(),
             py::arg("configuration") = ShotConfiguration{}, py::arg("threads") = 0,
             R"(Many strokes on one layout: predict_shot for each row of `strokes` (an (N, 5) array of phi, theta,
speed, a, b), on `threads` threads (0: one per core) with the GIL released. Returns a dict of numpy arrays: ids (the
balls' order, the cue ball first), velocity and angular_velocity (N, 3) of the cue ball after the strike,
final_position (N, B, 3) and pocket (N, B strings: the pocket's id, "" when not pocketed) of every ball, and error
(N: None, or the row's Error; its row's numbers are NaN and its pockets ""). A bad array, layout or thread count raises Error.)");
  module.def("strike_many", &strikeMany, py::arg("strokes"), py::arg("cue_ball"), py::arg("balls") = py::none(),
             py::arg("configuration") = ShotConfiguration{}, py::arg("threads") = 0,
             R"(Many strikes on one layout: strike() for each row of `strokes` (an (N, 5) array of phi, theta, speed,
a, b), on `threads` threads (0: one per core) with the GIL released; the balls' paths are not computed. Returns a dict
of numpy arrays: ids, velocity and angular_velocity (N, 3) of the cue ball right after the strike, other_velocity and
other_angular_velocity (N, B-1, 3) of the other balls (zero for a ball the strike did not touch: only balls frozen
to the cue ball move in it), miscue and leaves_cloth (N,), and error (N: None, or the row's Error; its numbers NaN).)");
}

}  // namespace billiard_shot_planner::python
