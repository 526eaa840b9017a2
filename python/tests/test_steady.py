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


@pytest.mark.parametrize("deck", ["Main_Aero.fst", "Main_ROSCO.fst"])  # ROSCO's: trimmed with its controller
def test_campbell_along_the_wind_equals_the_cli(deck, tmp_path):
    path = case("nrel5mw", deck)
    code, _, err = cli("campbell", path, "--wind", "12:1:12", "--azimuths", 4, "--no-plot", "--out", tmp_path)
    assert code == 0, err
    expected = pd.read_csv(tmp_path / "campbell.csv", float_precision="round_trip")
    got = whirl.load(path).campbell(wind=[12], azimuths=4)
    assert got.attrs["versus"] == "wind"
    assert list(got["mode"]) == list(expected["mode"])
    for c in ("rpm", "wind_speed", "freq_hz", "damping_ratio"):
        np.testing.assert_array_equal(got[c].to_numpy(), expected[c].to_numpy(), err_msg=c)


def test_structural_model_has_no_steady(onshore):
    with pytest.raises(whirl.InputError, match="has no aerodynamics"):
        onshore.steady(wind=[8])


def test_rosco_deck_trims_with_its_controller_as_the_cli(tmp_path):
    """Main_ROSCO.fst names ROSCO's DISCON.IN: `whirl steady` trims where that controller settles
    (region column "ROSCO 2", "ROSCO 3"); the module reads the same controller."""
    deck = case("nrel5mw", "Main_ROSCO.fst")
    code, _, err = cli("steady", deck, "--wind", "8:6:14", "--no-plot", "--out", tmp_path)
    assert code == 0, err
    expected = pd.read_csv(tmp_path / "steady.csv", float_precision="round_trip")
    seen = []
    got = whirl.load(deck).steady(wind=[8, 14], progress=lambda done, total: seen.append((done, total)))
    assert list(got["region"]) == ["ROSCO 2", "ROSCO 3"]
    pd.testing.assert_frame_equal(got, expected, check_exact=True, check_dtype=False)
    assert seen == [(1, 2), (2, 2)]


def test_interrupting_the_trims(aero):
    def interrupt(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        aero.steady(wind=[8, 9, 10], progress=interrupt)
    with pytest.raises(KeyboardInterrupt):
        aero.campbell(wind=[8, 9], azimuths=2, progress=interrupt)  # stopped in the trims
    assert len(aero.steady(wind=[8])) == 1  # the model stays usable
