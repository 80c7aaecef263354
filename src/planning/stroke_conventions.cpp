#include "billiard_shot_planner/planning/stroke_conventions.hpp"

#include <cmath>

namespace billiard_shot_planner
{
namespace
{
constexpr double DEGREE = M_PI / 180.0;
constexpr double MILLIMETRE = 1e-3;
/// pooltool's +x is this package's −y and FastFiz's +x this package's +y: a heading there is this much less or more
/// here (pooltool's foot, +y, is this package's +x; FastFiz's foot, −y, too).
constexpr double POOLTOOL_TURN = -90.0 * DEGREE;
constexpr double FASTFIZ_TURN = 90.0 * DEGREE;

/// The angle in (−π, π].
double wrapped(double angle)
{
  const double turned = std::remainder(angle, 2.0 * M_PI);
  return turned <= -M_PI ? turned + 2.0 * M_PI : turned;
}
}  // namespace

Stroke fromPooltool(const PooltoolStroke& s)
{
  return {wrapped(s.phi * DEGREE + POOLTOOL_TURN), s.theta * DEGREE, s.V0, -s.a, s.b};
}

PooltoolStroke toPooltool(const Stroke& s)
{
  return {s.speed, wrapped(s.phi - POOLTOOL_TURN) / DEGREE, s.theta / DEGREE, -s.a, s.b};
}

Stroke fromFastFiz(const FastFizShot& s, double ball_radius)
{
  const double per_radius = MILLIMETRE / ball_radius;
  return {wrapped(s.phi * DEGREE + FASTFIZ_TURN), s.theta * DEGREE, s.v, s.a * per_radius, s.b * per_radius};
}

FastFizShot toFastFiz(const Stroke& s, double ball_radius)
{
  const double millimetres = ball_radius / MILLIMETRE;
  return {s.a * millimetres, s.b * millimetres, s.theta / DEGREE, wrapped(s.phi - FASTFIZ_TURN) / DEGREE, s.speed};
}

Eigen::Vector2d fromPooltoolPosition(const Eigen::Vector2d& p, const Table& table)
{
  return {p.y() - 0.5 * table.length, 0.5 * table.width - p.x()};
}

Eigen::Vector2d toPooltoolPosition(const Eigen::Vector2d& p, const Table& table)
{
  return {0.5 * table.width - p.y(), p.x() + 0.5 * table.length};
}

Eigen::Vector2d fromFastFizPosition(const Eigen::Vector2d& p, const Table& table)
{
  return {0.5 * table.length - p.y(), p.x() - 0.5 * table.width};
}

Eigen::Vector2d toFastFizPosition(const Eigen::Vector2d& p, const Table& table)
{
  return {p.y() + 0.5 * table.width, 0.5 * table.length - p.x()};
}

}  // namespace billiard_shot_planner
