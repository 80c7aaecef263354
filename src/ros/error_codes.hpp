#pragma once

// The core's typed errors as the node's ErrorCode message: one mapping for every service and action.
#include <billiard_shot_planner/ErrorCode.h>
#include <tf2/exceptions.h>

#include <string>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// The message's code for a core error (msg/ErrorCode.msg).
ErrorCode errorCodeOf(const Error& error);

/// The constant's name of an ErrorCode value ("TRANSFORM_FAILED"; "UNKNOWN" for a value the message lacks).
const char* errorCodeName(int32_t val);

/// ErrorCode{val}, e.g. errorCode(ErrorCode::SUCCESS).
ErrorCode errorCode(int32_t val);

/// A tf failure on the request's `field` as a core error: a malformed argument (an empty or invalid frame id) is the
/// request's (InvalidArgument); a frame tf cannot place, or not at that time, is Unavailable (TRANSFORM_FAILED): a
/// retry may succeed once the transform is published.
Error transformError(const std::string& field, const tf2::TransformException& exception);

}  // namespace billiard_shot_planner
