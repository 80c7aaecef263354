#pragma once

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/laws/linear_spring.hpp"

namespace billiard_shot_planner
{
/// Energetic restitution that falls with the impact's speed as it does for elastic–perfectly-plastic spheres
/// (Thornton 1997, J. Appl. Mech. 64:383): Hertzian contact up to the yield speed v_y, above it a contact pressure
/// capped at the yield stress, whose plastic work grows faster than the impact's energy. For x = v_y / v > 0 below 1,
///
///   e_T(v) = √(6√3/5) · √(1 − x²/6) · [x / (x + 2√(6/5 − x²/5))]^¼,
///
/// 1 at v = v_y and falling as v^(−¼) far above it. The contact's `restitution` e0 is the restitution below the
/// yield speed (losses the elastic–plastic picture leaves out: the cloth under a cushion, the rubber's hysteresis),
/// and the law is e(v) = e0 · e_T(v) (docs/impact_model.md, "Restitution that depends on the impact"). Its spring is
/// linear: the speed enters only through the restitution of each compression.
struct ElasticPlasticRestitution
{
  static constexpr const char* TYPE = "elastic_plastic";

  double yield_speed = 1.0;  ///< v_y (m/s, > 0): the approach speed at which the contact starts to yield

  /// The spring: linear, F = −k s.
  LinearSpring spring() const { return {}; }
  template <class Visitor>
  void visitParameters(Visitor&& visit)
  {
    visit("yield_speed", yield_speed);
  }
  /// v_y finite and > 0, named `field`.yield_speed.
  Status validate(const std::string& field) const;
  /// e0 · e_T(v) for the energy-equivalent approach speed v = `impact_speed` (m/s).
  double restitution(double low_speed_restitution, double impact_speed) const;
};

}  // namespace billiard_shot_planner
