# libFuzzer targets of the physics core and the JSON front end, built with the package's own libraries when the
# project is configured with -DBILLIARD_SHOT_PLANNER_FUZZ=ON, clang and, in CMAKE_CXX_FLAGS, the sanitizers and
# -fsanitize=fuzzer-no-link (scripts/common.sh's configure_sanitized_build: build-asan/, which the sanitized tests
# share, so that the libraries are compiled once for both). The targets land in build-asan/fuzz/.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "BILLIARD_SHOT_PLANNER_FUZZ needs clang: configure with CXX=clang++ (Debian: clang, libclang-rt-14-dev)")
endif()

foreach(target fuzz_impact_engine fuzz_json_problems)
  add_executable(${target} EXCLUDE_FROM_ALL fuzz/${target}.cpp)
  target_link_options(${target} PRIVATE -fsanitize=fuzzer)
endforeach()
target_link_libraries(fuzz_impact_engine ${PROJECT_NAME}_core)
target_link_libraries(fuzz_json_problems ${PROJECT_NAME}_io)

# Writes fuzz/corpus/fuzz_impact_engine (a plain program; the sanitizers check it too).
add_executable(make_engine_seeds EXCLUDE_FROM_ALL fuzz/make_engine_seeds.cpp)
target_link_libraries(make_engine_seeds ${PROJECT_NAME}_core)

set_target_properties(fuzz_impact_engine fuzz_json_problems make_engine_seeds PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
