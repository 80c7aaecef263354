#pragma once

#include <string>
#include <utility>
#include <variant>

namespace billiard_shot_planner
{
/// What kind of failure a core call reports. Callers branch on the code; the message is for people.
enum class ErrorKind
{
  InvalidArgument,       ///< a field is NaN, infinite, out of range or inconsistent
  NoApproachingContact,  ///< nothing collides: no contact has a negative normal velocity
  InvalidShot,           ///< the cue cannot strike the ball as described
  EventLimitExceeded,    ///< the state sequence did not finish within the configured number of events
  StepLimitExceeded,     ///< the integrator did not finish within the configured number of steps
  TimeLimitExceeded,     ///< the call did not finish within its wall-clock budget
  NumericalFailure,      ///< the integrator or a root finder failed
  Unavailable,           ///< an input the call needs is not available (yet): a retry may succeed
  Stale,                 ///< an input is older than the caller allows: a fresh one is needed
  BallsMoving,           ///< the call needs the balls at rest and one moves: wait until they stop
};

const char* toString(ErrorKind code);

/// A typed error: the code, the offending field (dotted path, may be empty) and a readable message.
struct Error
{
  ErrorKind code = ErrorKind::InvalidArgument;
  std::string field;
  std::string message;

  /// "field: message" (or just the message when no field applies).
  std::string describe() const { return field.empty() ? message : field + ": " + message; }
};

inline Error invalidArgument(std::string field, std::string message)
{
  return Error{ErrorKind::InvalidArgument, std::move(field), std::move(message)};
}

/// A value or an Error. The core library reports every expected failure through this type and never throws
/// across its boundary.
template <class T>
class Expected
{
public:
  Expected(T value) : content_(std::move(value)) {}
  Expected(Error error) : content_(std::move(error)) {}

  bool ok() const { return std::holds_alternative<T>(content_); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { return std::get<T>(content_); }
  T& value() & { return std::get<T>(content_); }
  T&& value() && { return std::get<T>(std::move(content_)); }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }

  const Error& error() const { return std::get<Error>(content_); }

private:
  std::variant<T, Error> content_;
};

/// Expected<void>: success, or an Error.
class Status
{
public:
  Status() = default;
  Status(Error error) : error_(std::move(error)), ok_(false) {}

  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const { return error_; }

private:
  Error error_;
  bool ok_ = true;
};

}  // namespace billiard_shot_planner
