#pragma once

#include <string>
#include <variant>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/laws/constant_restitution.hpp"
#include "billiard_shot_planner/impact/laws/elastic_plastic_restitution.hpp"

namespace billiard_shot_planner
{
/// A contact's normal law: one immutable type with its own parameters (docs/extending.md, "A new contact law"). A
/// law is its spring (spring(): the force, stored energy and rate, the tangent stiffness, the restitution phase's
/// stiffness and deformation after an end of compression, and whether it is linear, LINEAR, which gates the closed
/// form of a phase) and its restitution (the energy an end of compression keeps). Every law registered here has the
/// linear spring (LinearSpring) and differs in its restitution. The first alternative is the default.
using NormalLaw = std::variant<ConstantRestitution, ElasticPlasticRestitution>;

/// The law's type as configuration names it ("constant", "elastic_plastic").
const char* lawType(const NormalLaw& law);
/// Whether the law's spring is linear (its spring's LINEAR).
bool isLinear(const NormalLaw& law);
/// Every registered type, in the variant's order.
std::vector<std::string> lawTypes();
/// The law of a type, with its default parameters; an error naming `field`.type lists the types there are.
Expected<NormalLaw> lawOfType(const std::string& type, const std::string& field);
/// The law's parameters checked, each error naming `field`.<parameter>.
Status validate(const NormalLaw& law, const std::string& field);
/// A key of a law's configuration: "type" or one of the law's parameters. Error: InvalidArgument naming
/// `field`.<key>, for a key the law does not have (a misspelt parameter is an error, not a default).
Status requireLawKey(const NormalLaw& law, const std::string& key, const std::string& field);
/// The restitution of one compression: e0 = `low_speed_restitution` under the law, at the energy-equivalent
/// approach speed `impact_speed` (m/s; docs/impact_model.md, "Restitution that depends on the impact").
double restitutionOf(const NormalLaw& law, double low_speed_restitution, double impact_speed);

/// Calls visit(name, double&) for every parameter of the law: the one declaration that the JSON, YAML and ROS front
/// ends read and write.
template <class Visitor>
void visitLawParameters(NormalLaw& law, Visitor&& visit)
{
  std::visit([&](auto& alternative) { alternative.visitParameters(visit); }, law);
}

}  // namespace billiard_shot_planner
