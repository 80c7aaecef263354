"""The bindings never crash the interpreter: fuzz_bindings.py throws random and hostile arguments at every entry point
in a child process, which must end normally (a crash, an abort or an exception other than Error or pybind11's
TypeError fails it)."""
import pathlib
import subprocess
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent
ROUNDS = 100


@pytest.mark.parametrize("seed", [1, 2])
def test_random_arguments_never_crash_the_interpreter(seed):
    run = subprocess.run([sys.executable, str(HERE / "fuzz_bindings.py"), str(seed), str(ROUNDS)], capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    # Every round of every entry point ended in an answer or a refusal.
    for line in run.stdout.splitlines():
        entry, counts = line.split(": ")
        returned, refused = (int(part.split()[0]) for part in counts.split(", "))
        assert returned + refused == ROUNDS, line
