#pragma once

// Reading the small text files a user names (table files, parameter files): text_file.cpp.
#include <cstdint>
#include <string>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// Files of configuration are a few kilobytes: a larger one is no such file.
constexpr std::uintmax_t MAX_CONFIGURATION_FILE_BYTES = 1U << 20U;

/// The whole text of the regular file at `path`. Errors: InvalidArgument naming `field` for a path that is missing,
/// not a regular file (a directory, a device such as /dev/zero), larger than MAX_CONFIGURATION_FILE_BYTES or
/// unreadable.
Expected<std::string> readTextFile(const std::string& path, const std::string& field);

}  // namespace billiard_shot_planner
