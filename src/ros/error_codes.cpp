#include "error_codes.hpp"

namespace billiard_shot_planner
{
namespace
{
int32_t valueOf(ErrorKind kind)
{
  switch (kind)
  {
    case ErrorKind::InvalidArgument:
      return ErrorCode::INVALID_ARGUMENT;
    case ErrorKind::NoApproachingContact:
      return ErrorCode::NO_APPROACHING_CONTACT;
    case ErrorKind::InvalidShot:
      return ErrorCode::INVALID_SHOT;
    case ErrorKind::EventLimitExceeded:
      return ErrorCode::EVENT_LIMIT;
    case ErrorKind::StepLimitExceeded:
      return ErrorCode::STEP_LIMIT;
    case ErrorKind::TimeLimitExceeded:
      return ErrorCode::TIME_LIMIT;
    case ErrorKind::NumericalFailure:
      return ErrorCode::NUMERICAL_FAILURE;
    case ErrorKind::Unavailable:
      return ErrorCode::TRANSFORM_FAILED;
    case ErrorKind::Stale:
      return ErrorCode::STALE_INPUT;
    case ErrorKind::BallsMoving:
      return ErrorCode::BALLS_MOVING;
  }
  return ErrorCode::INVALID_ARGUMENT;
}
}  // namespace

ErrorCode errorCode(int32_t val)
{
  ErrorCode code;
  code.val = val;
  return code;
}

Error transformError(const std::string& field, const tf2::TransformException& exception)
{
  const bool malformed = dynamic_cast<const tf2::InvalidArgumentException*>(&exception) != nullptr;
  return Error{malformed ? ErrorKind::InvalidArgument : ErrorKind::Unavailable, field,
               std::string("no transform to the table frame: ") + exception.what()};
}

const char* errorCodeName(int32_t val)
{
  switch (val)
  {
    case ErrorCode::SUCCESS:
      return "SUCCESS";
    case ErrorCode::INVALID_ARGUMENT:
      return "INVALID_ARGUMENT";
    case ErrorCode::INVALID_SHOT:
      return "INVALID_SHOT";
    case ErrorCode::NO_APPROACHING_CONTACT:
      return "NO_APPROACHING_CONTACT";
    case ErrorCode::TRANSFORM_FAILED:
      return "TRANSFORM_FAILED";
    case ErrorCode::STALE_INPUT:
      return "STALE_INPUT";
    case ErrorCode::BALLS_MOVING:
      return "BALLS_MOVING";
    case ErrorCode::TIME_LIMIT:
      return "TIME_LIMIT";
    case ErrorCode::EVENT_LIMIT:
      return "EVENT_LIMIT";
    case ErrorCode::STEP_LIMIT:
      return "STEP_LIMIT";
    case ErrorCode::NUMERICAL_FAILURE:
      return "NUMERICAL_FAILURE";
    case ErrorCode::NO_SHOT_FOUND:
      return "NO_SHOT_FOUND";
    default:
      return "UNKNOWN";
  }
}

ErrorCode errorCodeOf(const Error& error)
{
  return errorCode(valueOf(error.code));
}

}  // namespace billiard_shot_planner
