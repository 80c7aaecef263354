#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"

namespace billiard_shot_planner
{
const char* toString(ErrorKind code)
{
  switch (code)
  {
    case ErrorKind::InvalidArgument:
      return "invalid_argument";
    case ErrorKind::NoApproachingContact:
      return "no_approaching_contact";
    case ErrorKind::InvalidShot:
      return "invalid_shot";
    case ErrorKind::EventLimitExceeded:
      return "event_limit_exceeded";
    case ErrorKind::StepLimitExceeded:
      return "step_limit_exceeded";
    case ErrorKind::TimeLimitExceeded:
      return "time_limit_exceeded";
    case ErrorKind::NumericalFailure:
      return "numerical_failure";
    case ErrorKind::Unavailable:
      return "unavailable";
    case ErrorKind::Stale:
      return "stale";
    case ErrorKind::BallsMoving:
      return "balls_moving";
  }
  return "unknown";
}

const char* toString(ContactEventType type)
{
  switch (type)
  {
    case ContactEventType::EndOfCompression:
      return "end_of_compression";
    case ContactEventType::RestartOfCompression:
      return "restart_of_compression";
    case ContactEventType::Separation:
      return "separation";
    case ContactEventType::Reactivation:
      return "reactivation";
    case ContactEventType::StickToSlip:
      return "stick_to_slip";
    case ContactEventType::SlipToStick:
      return "slip_to_stick";
    case ContactEventType::RigidLink:
      return "rigid_link";
    case ContactEventType::LinkRelease:
      return "link_release";
  }
  return "unknown";
}

}  // namespace billiard_shot_planner
