#include "json_configuration.hpp"

#include "json_motion.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
Expected<ShotConfiguration> configurationOf(const json& request, const SolverOptions& options)
{
  auto setup = withMotion(strikePhysicsFromJson(request), request, options);
  if (!setup)
    return setup.error();
  auto contact = ballContactFromJson(request);
  if (!contact)
    return contact.error();
  const CueStrike& s = setup.value().strike;
  const MotionSetup& motion = setup.value().motion;
  ShotConfiguration c;
  c.cue_mass = s.cue_mass;
  c.cue_end_mass = s.cue_end_mass;
  c.ball_mass = s.ball_mass;
  c.ball_radius = s.ball_radius;
  c.cue_contact = s.cue_contact;
  c.stiffness_ratio = s.stiffness_ratio;
  c.table = motion.table;
  c.ball_contact = contact.value();
  c.motion = motion.parameters;
  c.solver = options;
  return c;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
