#pragma once
// The byte format of fuzz_impact_engine: an ImpactProblem and SolverOptions read with libFuzzer's
// FuzzedDataProvider, and the encoder that writes the same format (make_engine_seeds builds the seed corpus with it).
//
// FuzzedDataProvider takes integers from the END of the input, most significant byte first; every field below is an
// integer (a double is a selector byte and then its payload), so an input is the reversed sequence of the bytes the
// decoder consumes. An exhausted input reads as zeros: 0.0, false, the smallest value of a range.
#include <fuzzer/FuzzedDataProvider.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace fuzz_engine
{
using billiard_shot_planner::Contact;
using billiard_shot_planner::ImpactProblem;
using billiard_shot_planner::SolverOptions;

constexpr int MAX_DOFS = 9;
constexpr int MAX_CONTACTS = 6;
/// The fuzzer caps the integrator so that inputs which merely run to the step limit do not read as hangs: a step
/// costs 5-25 us natively but about 0.2 ms under the sanitizers (50 000 steps took 8-11 s, over libFuzzer's
/// -timeout=10; the engine's default is 300 000). 0 in the input means this cap.
constexpr std::uint32_t MAX_STEPS_CAP = 10000;
/// The wall-clock budget of every fuzzed solve, s (SolverOptions::max_seconds; the library's default is 10).
constexpr double MAX_SECONDS_CAP = 2.0;

/// Selector byte of a double: [0, 160) a decimal q/1000 (q a 16-bit signed integer), [160, 200) q·2^e with
/// e in [-64, 64], [200, 240) the raw 64 bits (NaN, infinities, subnormals), [240, 256) SPECIALS.
constexpr std::uint8_t SELECT_SCALED = 160;
constexpr std::uint8_t SELECT_RAW = 200;
constexpr std::uint8_t SELECT_SPECIAL = 240;
constexpr double SPECIALS[16] = {0.0,
                                 -0.0,
                                 1.0,
                                 -1.0,
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::min(),
                                 std::numeric_limits<double>::denorm_min(),
                                 std::numeric_limits<double>::max(),
                                 -std::numeric_limits<double>::max(),
                                 std::numeric_limits<double>::epsilon(),
                                 1e-300,
                                 1e300,
                                 0.5,
                                 1e-8};

/// How the mass matrix is built from the input.
enum class MassForm : int
{
  Diagonal = 0,   ///< |d_i| on the diagonal
  Gram = 1,       ///< A·Aᵀ + |s|·I: symmetric positive semi-definite, definite unless s = 0 and A is singular
  Symmetric = 2,  ///< the upper triangle, mirrored: anything symmetric
  Arbitrary = 3,  ///< every entry: usually not symmetric (validation must refuse it)
};

/// Shape of one contact's Jacobian: the well-formed ones, and sizes that validation must refuse.
enum class ContactShape : int
{
  NormalOnly = 0,   ///< no tangent rows (valid when frictionless)
  WithTangent = 1,  ///< 2×d tangent rows
  WideTangent = 2,  ///< 2×(d+1) tangent rows
  WideNormal = 3,   ///< a normal of d+1 entries, 2×d tangent rows
};

struct EngineInput
{
  ImpactProblem problem;
  SolverOptions options;
};

inline double readDouble(FuzzedDataProvider& in)
{
  const auto select = in.ConsumeIntegral<std::uint8_t>();
  if (select < SELECT_SCALED)
    return static_cast<std::int16_t>(in.ConsumeIntegral<std::uint16_t>()) / 1000.0;
  if (select < SELECT_RAW)
  {
    const auto mantissa = static_cast<std::int16_t>(in.ConsumeIntegral<std::uint16_t>());
    return std::ldexp(static_cast<double>(mantissa), in.ConsumeIntegralInRange<int>(-64, 64));
  }
  if (select < SELECT_SPECIAL)
  {
    const auto bits = in.ConsumeIntegral<std::uint64_t>();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  return SPECIALS[select - SELECT_SPECIAL];
}

inline Eigen::MatrixXd readMatrix(FuzzedDataProvider& in, Eigen::Index rows, Eigen::Index cols)
{
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j)
      m(i, j) = readDouble(in);
  return m;
}

inline Eigen::MatrixXd readMassMatrix(FuzzedDataProvider& in, int dofs)
{
  const auto form = static_cast<MassForm>(in.ConsumeIntegralInRange<int>(0, 3));
  switch (form)
  {
    case MassForm::Diagonal:
      return readMatrix(in, dofs, 1).cwiseAbs().col(0).asDiagonal();
    case MassForm::Gram:
    {
      const Eigen::MatrixXd a = readMatrix(in, dofs, dofs);
      const double shift = std::abs(readDouble(in));
      return a * a.transpose() + shift * Eigen::MatrixXd::Identity(dofs, dofs);
    }
    case MassForm::Symmetric:
    {
      Eigen::MatrixXd m(dofs, dofs);
      for (int i = 0; i < dofs; ++i)
        for (int j = i; j < dofs; ++j)
          m(i, j) = m(j, i) = readDouble(in);
      return m;
    }
    case MassForm::Arbitrary:
      break;
  }
  return readMatrix(in, dofs, dofs);
}

inline Contact readContact(FuzzedDataProvider& in, int dofs)
{
  Contact contact;
  contact.name = "c";
  const auto shape = static_cast<ContactShape>(in.ConsumeIntegralInRange<int>(0, 3));
  const int normal_size = shape == ContactShape::WideNormal ? dofs + 1 : dofs;
  contact.normal = readMatrix(in, 1, normal_size);
  if (shape != ContactShape::NormalOnly)
    contact.tangent = readMatrix(in, 2, shape == ContactShape::WideTangent ? dofs + 1 : dofs);
  contact.law.restitution = readDouble(in);
  contact.law.stiffness = readDouble(in);
  contact.law.friction = readDouble(in);
  contact.law.eta2 = readDouble(in);
  return contact;
}

/// A tolerance: 0 the default, then a few typical values, 7 any double (mostly refused by validation).
inline double readTolerance(FuzzedDataProvider& in, double fallback)
{
  constexpr double CHOICES[] = {1e-6, 1e-9, 1e-3, std::numeric_limits<double>::epsilon(), 1e-14, 9.99e-3};
  const int choice = in.ConsumeIntegralInRange<int>(0, 7);
  if (choice == 0)
    return fallback;
  if (choice == 7)
    return readDouble(in);
  return CHOICES[choice - 1];
}

inline SolverOptions readOptions(FuzzedDataProvider& in)
{
  SolverOptions options;
  options.relative_tolerance = readTolerance(in, options.relative_tolerance);
  options.absolute_tolerance = readTolerance(in, options.absolute_tolerance);
  // Flags read as "turn off" so that an exhausted input keeps the defaults.
  options.closed_form_linear_phases = !in.ConsumeBool();
  options.separation_clock = !in.ConsumeBool();
  options.quasi_steady_slip = !in.ConsumeBool();
  options.record_samples = in.ConsumeBool();
  const auto max_events = in.ConsumeIntegralInRange<std::uint32_t>(0, 200000);
  options.max_events = max_events == 0 ? options.max_events : max_events;
  const auto max_steps = in.ConsumeIntegralInRange<std::uint32_t>(0, MAX_STEPS_CAP);
  options.max_steps = max_steps == 0 ? MAX_STEPS_CAP : max_steps;
  // Well inside libFuzzer's -timeout=10 under the sanitizers: a solve cut by its budget is an answer, not a hang.
  options.max_seconds = MAX_SECONDS_CAP;
  if (in.ConsumeBool())
  {
    options.chatter_energy_fraction = readDouble(in);
    options.chatter_stiffness_growth = readDouble(in);
    options.chatter_resolution = readDouble(in);
  }
  return options;
}

/// The whole input: dimension, mass matrix, velocity, contacts, whether to aim contact 0 at an approach, options.
inline EngineInput readEngineInput(FuzzedDataProvider& in)
{
  EngineInput input;
  ImpactProblem& problem = input.problem;
  const int dofs = in.ConsumeIntegralInRange<int>(1, MAX_DOFS);
  problem.mass_matrix = readMassMatrix(in, dofs);
  problem.velocity = readMatrix(in, dofs, 1).col(0);
  const int contacts = in.ConsumeIntegralInRange<int>(1, MAX_CONTACTS);
  for (int i = 0; i < contacts; ++i)
    problem.contacts.push_back(readContact(in, dofs));
  // Most random velocities approach no contact and are refused at once: on request, move u along contact 0's
  // normal until that contact approaches at the speed read here.
  if (in.ConsumeBool())
  {
    const Eigen::RowVectorXd& n = problem.contacts.front().normal;
    const double approach = std::abs(readDouble(in));
    if (n.size() == dofs && n.squaredNorm() > 0.0 && std::isfinite(n.squaredNorm()))
      problem.velocity -= ((n.dot(problem.velocity) + approach) / n.squaredNorm()) * n.transpose();
  }
  input.options = readOptions(in);
  return input;
}

/// Writes inputs in the format above (only the forms the seeds need: arbitrary mass matrices, exact doubles).
class EngineInputWriter
{
public:
  /// The input, ready for a file: the consumed bytes in reverse.
  std::vector<std::uint8_t> bytes() const { return {consumed_.rbegin(), consumed_.rend()}; }

  /// The inverse of FuzzedDataProvider::ConsumeIntegralInRange: as many bytes as the range needs, most significant
  /// first.
  void integer(std::int64_t value, std::int64_t min, std::int64_t max)
  {
    const auto range = static_cast<std::uint64_t>(max - min);
    const auto offset = static_cast<std::uint64_t>(value - min);
    int bytes = 0;
    while (bytes < 8 && (range >> (8 * bytes)) > 0)
      ++bytes;
    for (int i = bytes - 1; i >= 0; --i)
      consumed_.push_back(static_cast<std::uint8_t>(offset >> (8 * i)));
  }

  void boolean(bool value) { integer(value ? 1 : 0, 0, 255); }

  /// Exactly `value`: a decimal when q/1000 reproduces it, else the raw bits.
  void real(double value)
  {
    const double q = std::round(value * 1000.0);
    if (std::abs(q) <= 32767.0 && q / 1000.0 == value && !(value == 0.0 && std::signbit(value)))
    {
      integer(0, 0, 255);
      integer(static_cast<std::uint16_t>(static_cast<std::int16_t>(q)), 0, 65535);
      return;
    }
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    integer(SELECT_RAW, 0, 255);
    consumed_.insert(consumed_.end(), 8, 0);  // ConsumeIntegral<uint64_t>: 8 bytes, most significant first
    for (int i = 0; i < 8; ++i)
      consumed_[consumed_.size() - 8 + i] = static_cast<std::uint8_t>(bits >> (8 * (7 - i)));
  }

  void matrix(const Eigen::MatrixXd& m)
  {
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j)
        real(m(i, j));
  }

  /// A problem whose mass matrix is written entry by entry and whose contacts all have tangent rows when
  /// frictional; no aiming; default options but for `max_steps` (0: the fuzzer's cap).
  void problem(const ImpactProblem& p, bool aim = false, double approach = 0.0)
  {
    const auto dofs = p.mass_matrix.rows();
    integer(dofs, 1, MAX_DOFS);
    integer(static_cast<int>(MassForm::Arbitrary), 0, 3);
    matrix(p.mass_matrix);
    matrix(p.velocity);
    integer(static_cast<std::int64_t>(p.contacts.size()), 1, MAX_CONTACTS);
    for (const Contact& c : p.contacts)
    {
      const bool tangent = c.tangent.cols() == dofs;
      integer(static_cast<int>(tangent ? ContactShape::WithTangent : ContactShape::NormalOnly), 0, 3);
      matrix(c.normal);
      if (tangent)
        matrix(c.tangent);
      real(c.law.restitution);
      real(c.law.stiffness);
      real(c.law.friction);
      real(c.law.eta2);
    }
    boolean(aim);
    if (aim)
      real(approach);
  }

  /// Options: tolerance choices (0 default), flags as in readOptions, limits (0 default/cap).
  void options(int relative_choice, int absolute_choice, bool closed_form, bool separation_clock, bool quasi_steady,
               bool record_samples, std::uint32_t max_events, std::uint32_t max_steps)
  {
    integer(relative_choice, 0, 7);
    integer(absolute_choice, 0, 7);
    boolean(!closed_form);
    boolean(!separation_clock);
    boolean(!quasi_steady);
    boolean(record_samples);
    integer(max_events, 0, 200000);
    integer(max_steps, 0, MAX_STEPS_CAP);
    boolean(false);
  }

private:
  std::vector<std::uint8_t> consumed_;
};

}  // namespace fuzz_engine
