"""whirl.lin.read against `whirl lin` on OpenFAST .lin files (tests/data/openfast-lin: one operating
point at 9 rpm over three azimuths; the same library path, so the same numbers)."""
import io

import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import SOURCE, cli, cli_error

LIN = SOURCE / "tests" / "data" / "openfast-lin" / "rotating-9rpm"
FILES = [str(LIN / f"Main.{k}.lin") for k in (1, 12, 24)]


def test_lin_modes_equal_the_cli():
    code, out, err = cli("lin", *FILES, "--format", "csv")
    assert code == 0, err
    expected = pd.read_csv(io.StringIO(out), float_precision="round_trip")
    got = whirl.lin.read(FILES)
    # One operating point: the CLI prints the point's modes by frequency; the table holds the modes
    # on tracked lines (all but the rigid-body azimuth mode, which has no line), with the same numbers.
    for _, row in got.iterrows():
        same = expected[(expected["name"] == row["mode"]) & (expected["freq_hz"] == row["freq_hz"])]
        assert len(same) == 1, row["mode"]
        assert same["damping_ratio"].iloc[0] == row["damping_ratio"]
    assert len(got) >= len(expected) - 1
    assert np.allclose(got["rpm"], got["rpm"].iloc[0])  # one operating point


def test_missing_lin_file_has_the_cli_message(tmp_path):
    missing = str(tmp_path / "none.lin")
    with pytest.raises(whirl.InputError) as e:
        whirl.lin.read([missing])
    assert str(e.value) == cli_error("lin", missing)
