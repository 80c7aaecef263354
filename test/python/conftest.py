"""Shared by the Python tests: the package's directory, for its shipped files."""
import pathlib

PACKAGE_ROOT = pathlib.Path(__file__).resolve().parents[2]
