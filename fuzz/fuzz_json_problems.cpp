// libFuzzer target: bytes -> JSON (invalid JSON is refused as impact_solve refuses it) -> solveJsonProblem().
// Aborts, so that libFuzzer records the input, when a successful answer holds a NaN or infinite number (checked on
// the JSON values: dump() would print them as null). solveJsonProblem promises not to throw: an exception escaping
// it ends the run as a crash. Crashes, leaks and undefined behaviour are the sanitizers'; hangs are libFuzzer's
// -timeout.
//
// The problems of kind ball_motion and shot may name a "table_file": run the fuzzer from the repository's root so
// that the seeds' config/table_9ft.yaml is found (and with standard input closed: a path of /dev/stdin would wait).
// FUZZ_VERBOSE=1 in the environment prints whether each input was solved or refused, and why.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "billiard_shot_planner/io/json_problems.hpp"

namespace
{
using nlohmann::json;

/// The path of the first NaN or infinite number in `value` ("" if none), e.g. "/strike/v/2".
std::string firstNonFinite(const json& value, const std::string& path)
{
  switch (value.type())
  {
    case json::value_t::number_float:
      return std::isfinite(value.get<double>()) ? "" : (path.empty() ? "/" : path);
    case json::value_t::object:
      for (const auto& [key, item] : value.items())
        if (std::string found = firstNonFinite(item, path + "/" + key); !found.empty())
          return found;
      return "";
    case json::value_t::array:
      for (std::size_t i = 0; i < value.size(); ++i)
        if (std::string found = firstNonFinite(value[i], path + "/" + std::to_string(i)); !found.empty())
          return found;
      return "";
    default:
      return "";
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  json request = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (request.is_discarded())
    return 0;  // impact_solve: "input is not valid JSON", exit code 2
  // Every solve's wall-clock budget well inside libFuzzer's -timeout=10 under the sanitizers (the library's default
  // is 10 s): a solve cut by its budget is an answer, not a hang. A request's own budget is kept when smaller.
  if (request.is_object() && (!request.contains("solver") || request["solver"].is_object()))
  {
    json& solver = request["solver"];
    if (!solver.contains("max_seconds") || !solver["max_seconds"].is_number() ||
        !(solver["max_seconds"].get<double>() <= 2.0))
      solver["max_seconds"] = 2.0;
  }
  // The same for a plan's own budget: a plan ends within it plus one stroke's solve. A budget that is not a number
  // is kept, for the error it must give.
  if (request.is_object() && request.contains("budget_ms") && request["budget_ms"].is_number() &&
      !(request["budget_ms"].get<double>() <= 2000.0))
    request["budget_ms"] = 2000.0;
  // A fit's default budget is a minute: the harness gives it a tenth of a second, enough to read and check every
  // field and take a first step, so that fits do not crowd out the other problems' executions.
  if (request.is_object() && request.contains("problem") && request["problem"] == "calibrate" &&
      (!request.contains("budget_ms") ||
       (request["budget_ms"].is_number() && !(request["budget_ms"].get<double>() <= 100.0))))
    request["budget_ms"] = 100.0;
  const auto result = billiard_shot_planner::solveJsonProblem(request);
  static const bool verbose = std::getenv("FUZZ_VERBOSE") != nullptr;
  if (!result)
  {
    const std::string error = result.error().describe();
    if (verbose)
      std::fprintf(stderr, "refused: %s: %s\n", toString(result.error().code), error.c_str());
    return 0;
  }
  if (verbose)
    std::fprintf(stderr, "solved: %zu bytes of answer\n", result.value().dump().size());
  if (const std::string path = firstNonFinite(result.value(), ""); !path.empty())
  {
    std::fprintf(stderr, "fuzz_json_problems: the answer has a NaN or infinite number at %s\n", path.c_str());
    std::abort();
  }
  try
  {
    (void)result.value().dump(2);  // as impact_solve prints it
  }
  catch (const json::exception& e)  // impact_solve reports it and exits 1
  {
    std::fprintf(stderr, "fuzz_json_problems: the answer cannot be printed: %s\n", e.what());
  }
  return 0;
}
