# The Python package billiard_shot_planner: its modules in src/billiard_shot_planner/ (the catkin convention, beside
# the generated msg and srv modules) and its compiled core, the extension _core built from src/python/ with pybind11.
# With catkin, the extension goes to the devel space's package directory (importable after sourcing the workspace)
# and catkin_python_setup() installs the modules. Without ROS, build/python/billiard_shot_planner/ holds the whole
# package (PYTHONPATH=build/python) and cmake --install puts it in ${BSP_PYTHON_DESTINATION}.
find_package(pybind11 REQUIRED)

# A MODULE library with pybind11's usage requirements (pybind11_add_module's parts, spelled out for catkin_lint).
add_library(${PROJECT_NAME}_python MODULE
  src/python/batch_binding.cpp
  src/python/configuration_binding.cpp
  src/python/fit_binding.cpp
  src/python/impact_binding.cpp
  src/python/layout.cpp
  src/python/module.cpp
  src/python/plan_binding.cpp
  src/python/python_errors.cpp
  src/python/shot_binding.cpp
)
target_link_libraries(${PROJECT_NAME}_python PRIVATE ${PROJECT_NAME}_io pybind11::module)
pybind11_extension(${PROJECT_NAME}_python)  # the interpreter's suffix (_core.cpython-311-x86_64-linux-gnu.so)
set_target_properties(${PROJECT_NAME}_python PROPERTIES OUTPUT_NAME _core CXX_VISIBILITY_PRESET hidden
                      LIBRARY_OUTPUT_DIRECTORY ${BSP_PYTHON_BUILD_DIR})
install(TARGETS ${PROJECT_NAME}_python LIBRARY DESTINATION ${BSP_PYTHON_DESTINATION})

# Without catkin_python_setup(), the modules are copied beside the extension and installed with it. The stubs go with
# both builds (catkin installs only .py files).
if(NOT BILLIARD_SHOT_PLANNER_ROS)
  foreach(source __init__.py distributed.py _core.pyi py.typed)
    configure_file(src/${PROJECT_NAME}/${source} ${BSP_PYTHON_BUILD_DIR}/${source} COPYONLY)
  endforeach()
  install(FILES src/${PROJECT_NAME}/__init__.py src/${PROJECT_NAME}/distributed.py DESTINATION ${BSP_PYTHON_DESTINATION})
endif()
install(FILES src/${PROJECT_NAME}/_core.pyi src/${PROJECT_NAME}/py.typed DESTINATION ${BSP_PYTHON_DESTINATION})

# The Python tests (pytest) against the package this build made: the build tree's without ROS, the devel space's
# (through its env.sh) with catkin.
if(BILLIARD_SHOT_PLANNER_ROS)
  if(CATKIN_ENABLE_TESTING)
    add_test(NAME python_tests COMMAND ${CATKIN_DEVEL_PREFIX}/env.sh ${CMAKE_COMMAND} -E env PYTHONDONTWRITEBYTECODE=1
                                       /usr/bin/python3 -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/test/python)
  endif()
else()
  enable_testing()
  add_test(NAME python_tests COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${CMAKE_BINARY_DIR}/python PYTHONDONTWRITEBYTECODE=1
                                     /usr/bin/python3 -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/test/python)
endif()
