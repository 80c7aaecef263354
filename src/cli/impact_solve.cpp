// impact_solve: one JSON problem on standard input, one JSON result on standard output.
// Exit codes: 0 solved, 2 bad input (message on standard error), 1 the solver failed on valid input.
#include <iostream>
#include <iterator>
#include <string>

#include "billiard_shot_planner/io/json_problems.hpp"

namespace
{
int run()
{
  using billiard_shot_planner::ErrorKind;
  const std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  const nlohmann::json request = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (request.is_discarded())
  {
    std::cerr << "impact_solve: input is not valid JSON\n";
    return 2;
  }
  const auto result = billiard_shot_planner::solveJsonProblem(request);
  if (!result)
  {
    const auto& error = result.error();
    std::cerr << "impact_solve: " << toString(error.code) << ": " << error.describe() << "\n";
    const bool bad_input = error.code == ErrorKind::InvalidArgument || error.code == ErrorKind::InvalidShot ||
                           error.code == ErrorKind::NoApproachingContact;
    return bad_input ? 2 : 1;
  }
  std::cout << result.value().dump(2) << "\n";
  return 0;
}
}  // namespace

int main()
{
  try
  {
    return run();
  }
  catch (const std::exception& e)  // e.g. output that cannot be encoded; the library itself does not throw
  {
    std::cerr << "impact_solve: " << e.what() << "\n";
    return 1;
  }
}
