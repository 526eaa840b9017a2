"""Model.steady against `whirl steady` (the same trim and the same table code: equal numbers), and the
aeroelastic Campbell diagram along the wind against `whirl campbell --wind`."""
import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import case, cli

AERO = case("nrel5mw", "Main_Aero.fst")


@pytest.fixture(scope="module")
def aero():
    return whirl.load(AERO)


def test_steady_equals_the_cli_table(aero, tmp_path):
    code, _, err = cli("steady", AERO, "--wind", "8:4:12", "--no-plot", "--out", tmp_path)
    assert code == 0, err
    expected = pd.read_csv(tmp_path / "steady.csv", float_precision="round_trip")
    got = aero.steady(wind=[8, 12])
    assert list(got.columns) == list(expected.columns)
    # The CLI writes 8 for 8.0 (shortest round trip), which pandas reads as an integer column.
    pd.testing.assert_frame_equal(got, expected, check_exact=True, check_dtype=False)


def test_campbell_along_the_wind_equals_the_cli(aero, tmp_path):
    code, _, err = cli("campbell", AERO, "--wind", "12:1:12", "--azimuths", 4, "--no-plot", "--out", tmp_path)
    assert code == 0, err
    expected = pd.read_csv(tmp_path / "campbell.csv", float_precision="round_trip")
    got = aero.campbell(wind=[12], azimuths=4)
    assert got.attrs["versus"] == "wind"
    assert list(got["mode"]) == list(expected["mode"])
    for c in ("rpm", "wind_speed", "freq_hz", "damping_ratio"):
        np.testing.assert_array_equal(got[c].to_numpy(), expected[c].to_numpy(), err_msg=c)


def test_structural_model_has_no_steady(onshore):
    with pytest.raises(whirl.InputError, match="has no aerodynamics"):
        onshore.steady(wind=[8])
