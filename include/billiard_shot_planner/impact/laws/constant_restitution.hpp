#pragma once

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/laws/linear_spring.hpp"

namespace billiard_shot_planner
{
/// The paper's energetic restitution (§3.3): every end of compression keeps the fraction e² of the normal strain
/// energy, e the contact's `restitution`, whatever the impact's speed. With linear springs the impact then has no
/// velocity scale: its answers scale with the velocities (docs/impact_model.md, Scaling). Its spring is linear.
struct ConstantRestitution
{
  static constexpr const char* TYPE = "constant";

  /// The spring: linear, F = −k s.
  LinearSpring spring() const { return {}; }
  /// No parameters beyond the contact's restitution.
  template <class Visitor>
  void visitParameters(Visitor&& /*visit*/)
  {
  }
  Status validate(const std::string& /*field*/) const { return {}; }
  /// The restitution of a compression whose energy-equivalent approach speed is `impact_speed` (m/s).
  double restitution(double low_speed_restitution, double /*impact_speed*/) const { return low_speed_restitution; }
};

}  // namespace billiard_shot_planner
