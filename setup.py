# catkin_python_setup() reads this: the Python package in src/billiard_shot_planner (its compiled core, _core, is
# built by CMake: cmake/python_package.cmake). Not for pip: the package is built and installed with CMake.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["billiard_shot_planner"], package_dir={"": "src"}))
