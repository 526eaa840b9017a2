"""Model.bode: the table of `whirl bode` (same inputs, same code path: bode.csv's numbers, bit for
bit), the static gains the CLI prints, files only when asked."""
import re

import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import case, cli

ONSHORE = case("nrel5mw", "Main_Onshore.fst")
ARGS = dict(inputs=["generator torque"], outputs=["GenSpeed", "TTDspFA"], rpm=12, azimuths=4, points=50)


@pytest.fixture(scope="module")
def cli_bode(tmp_path_factory):
    out = tmp_path_factory.mktemp("bode_cli")
    code, stdout, err = cli("bode", ONSHORE, "--rpm", 12, "--inputs", "generator torque", "--outputs", "GenSpeed,TTDspFA",
                            "--azimuths", 4, "--points", 50, "--out", out, "--no-plot")
    assert code == 0, err
    return out, stdout


@pytest.fixture(scope="module")
def table(onshore):
    return onshore.bode(**ARGS)


def test_table_equals_bode_csv(table, cli_bode):
    csv = pd.read_csv(cli_bode[0] / "bode.csv", index_col=0, float_precision="round_trip")
    assert list(table.columns) == list(csv.columns)
    np.testing.assert_array_equal(table.index.to_numpy(), csv.index.to_numpy())
    np.testing.assert_array_equal(table.to_numpy(), csv.to_numpy())  # shortest round trip: the same bits
    assert isinstance(table, whirl.BodeTable)


def test_static_gain_as_printed(table, cli_bode):
    printed = dict(re.findall(r"^  (.+): (\S+)$", cli_bode[1], re.M))
    assert set(printed) == set(table.attrs["static_gain"])
    for pair, value in table.attrs["static_gain"].items():
        assert f"{value:.6g}" == printed[pair]  # the CLI prints %.6g


def test_files_only_when_asked(onshore, cli_bode, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    onshore.bode(**ARGS)
    assert list(tmp_path.iterdir()) == []
    onshore.bode(**ARGS, out=tmp_path / "out", plot=False)
    for name in ("bode.csv", "bode.gp"):
        assert (tmp_path / "out" / name).read_bytes() == (cli_bode[0] / name).read_bytes(), name


def test_bad_input(onshore):
    with pytest.raises(whirl.InputError, match="unknown output 'nope'"):
        onshore.bode(inputs=["generator torque"], outputs=["nope"], rpm=12, azimuths=2)
    with pytest.raises(whirl.InputError, match="wind= \\(trimmed\\) or rpm="):
        onshore.bode(inputs=["generator torque"], outputs=["GenSpeed"], rpm=12, wind=8)


def test_argument_messages(onshore):
    with pytest.raises(whirl.InputError, match="bode: give inputs= and outputs="):
        onshore.bode(inputs=[], outputs=["GenSpeed"])
    with pytest.raises(whirl.InputError, match="points: must be in 2"):
        onshore.bode(inputs=["generator torque"], outputs=["GenSpeed"], points=1)
    with pytest.raises(whirl.InputError, match="frequencies: need 0 < F0 < F1"):
        onshore.bode(inputs=["generator torque"], outputs=["GenSpeed"], f_from=1.0, f_to=0.5)
