#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/impact/contact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The cue tip as the leading degrees of freedom of a strike's impact problem, and its contact with the struck ball:
/// shared by the lone strike (cue_strike.cpp) and the strike of a ball that touches others (cluster_strike.cpp).

/// Checks the strike's fields and that the cue approaches the ball at the hit point.
Status checkStrike(const CueStrike& strike);

/// The tip's degrees of freedom: along ĉ, and across it (two) when its end mass is finite.
int tipDofs(const CueStrike& strike);

/// Unit directions of the tip's degrees of freedom, as columns: ĉ, then two axes across it.
Eigen::Matrix3d tipAxes(const Eigen::Vector3d& cue_direction);

/// Writes the tip's masses on the diagonal's first tipDofs() entries and its velocity (the cue's speed along ĉ).
void setTip(const CueStrike& strike, Eigen::MatrixXd& mass_matrix, Eigen::VectorXd& velocity);

/// The cue–ball contact: A = the tip, B = the ball whose (v, ω) start at coordinate `ball`, so that
/// w = d·(tip velocity) − d·(v + ω × r n̂).
Contact cueContact(const CueStrike& strike, const char* name, Eigen::Index ball, Eigen::Index coordinates);

/// A contact's impulse in world axes, from its contact frame.
Eigen::Vector3d worldImpulse(const ContactImpulse& impulse, const Eigen::Matrix3d& frame);

/// The cue's and the struck ball's part of a strike's answer (velocities, impulse on the cue, miscue, leaving the
/// cloth) from the solved impact; the ball's (v, ω) start at coordinate `ball`. The table's impulse, the states and
/// the contacts are the caller's.
CueStrikeResult strikeResult(const CueStrike& strike, ImpactResult impact, Eigen::Index ball);
}  // namespace detail
}  // namespace billiard_shot_planner
