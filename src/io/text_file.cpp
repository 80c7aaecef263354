#include "text_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace billiard_shot_planner
{
Expected<std::string> readTextFile(const std::string& path, const std::string& field)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    return invalidArgument(field, "cannot open " + path + ": not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size > MAX_CONFIGURATION_FILE_BYTES)
    return invalidArgument(field, path + " is larger than a configuration file can be (1 MiB)");
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  if (!file || !text)
    return invalidArgument(field, "cannot open " + path);
  return text.str();
}

}  // namespace billiard_shot_planner
