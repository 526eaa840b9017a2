"""Shared by the Python tests: where the repository and the CLI are (set by CTest, test python_pytest;
by hand: PYTHONPATH=build/python WHIRL_BINARY=build/whirl /usr/bin/python3 -m pytest python/tests)."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("WHIRL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("WHIRL_BINARY", str(SOURCE / "build" / "whirl"))


def case(*parts) -> str:
    """A path under cases/."""
    return str(SOURCE.joinpath("cases", *parts))


def cli(*args, cwd=None):
    """Runs the CLI; (exit code, stdout, stderr)."""
    r = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=600)
    return r.returncode, r.stdout, r.stderr


def cli_error(*args) -> str:
    """The CLI's error message (the `whirl: error: ` line without its prefix) of a failing command."""
    code, _, err = cli(*args)
    assert code != 0, err
    lines = [l for l in err.splitlines() if l.startswith("whirl: error: ")]
    assert lines, err
    return lines[0][len("whirl: error: "):]


@pytest.fixture(scope="session")
def onshore():
    import whirl
    return whirl.load(case("nrel5mw", "Main_Onshore.fst"))
