"""whirl.load(..., unsteady_aero=): the blade elements' unsteady-airfoil states (UA_Mod 4) in the linear
models as the deck asks, left out (quasi-steady) or insisted on, as the CLI's --quasi-steady-aero and
--unsteady-aero (docs/theory/unsteady-aero.md)."""
import json

import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import SOURCE, case, cli

# The NREL 5MW aeroelastic deck with its older AeroDyn switch turned to the HGM model (UA_Mod 4).
UA = {"AFAeroMod": 2, "UAMod": 4}


def _states(model):
    return model.linearize(model.operating_point(rpm=12, wind=12), azimuths=4).state_names


def test_states_as_the_deck_asks_and_quasi_steady_without_them(tmp_path):
    deck = case("nrel5mw", "Main_Aero.fst")
    with_ua = _states(whirl.load(deck, set=UA))
    quasi = _states(whirl.load(deck, set=UA, unsteady_aero=False))
    ua = [s for s in with_ua if s.startswith("UA x")]
    assert ua, with_ua
    assert not any(s.startswith("UA x") for s in quasi)
    assert [s for s in with_ua if not s.startswith("UA x")] == quasi
    # The same count as the CLI's export of the same deck, and its --quasi-steady-aero.
    for flag, expected in (((), with_ua), (("--quasi-steady-aero",), quasi)):
        code, _, err = cli("export", deck, "--set", "AFAeroMod=2", "--set", "UAMod=4", "--set", "HWindSpeed=12",
                           "--rpm", 12, "--azimuths", 4, "--format", "json", *flag, "--out", tmp_path / str(len(flag)))
        assert code == 0, err
        doc = json.loads((tmp_path / str(len(flag)) / "statespace.json").read_text())
        assert len(doc["operating_points"][0]["model"]["states"]) == len(expected)


def test_dynamic_inflow_states_follow_the_same_choice():
    # OpenFAST's r-test Fake5MW_AeroLin_B1_UA4_DBEMT3: UA_Mod 4 and DBEMT_Mod 3, one blade.
    deck = str(SOURCE / "tests/data/openfast-lin/ua4-dbemt3/case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst")
    names = whirl.load(deck).linearize(azimuths=1).state_names
    assert any(s.startswith("DBEMT") for s in names) and any(s.startswith("UA x") for s in names), names
    quasi = whirl.load(deck, unsteady_aero=False).linearize(azimuths=1).state_names
    assert not any(s.startswith(("DBEMT", "UA x")) for s in quasi), quasi


def test_asking_for_states_on_a_deck_without_them_is_the_cli_error():
    deck = case("nrel5mw", "Main_Aero.fst")  # AFAeroMod 1: steady airfoil tables
    with pytest.raises(whirl.InputError, match="--unsteady-aero: the deck's AeroDyn has no unsteady-airfoil states"):
        whirl.load(deck, unsteady_aero=True)
    assert whirl.load(deck, set=UA, unsteady_aero=True)  # the states are there: accepted



def test_simulate_integrates_the_states_as_the_cli(tmp_path):
    # The r-test one-blade rotor parked at 75 deg pitch, its flap released from 0.1 m: Model.simulate integrates
    # the deck's UA and DBEMT states as `whirl simulate` does (the same bits); with unsteady_aero=False it
    # integrates none, as --quasi-steady-aero. Fails when the Python path drops the states (it did).
    deck = str(SOURCE / "tests/data/openfast-lin/ua4-dbemt3/case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst")
    sets = {"RotSpeed": 0, "BlPitch(1)": 75}
    run = dict(tmax=0.5, equilibrium=True, init={"blade 1 flap 1+": 0.1}, plot=False)
    series = whirl.load(deck, set=sets).simulate(**run)
    assert series.attrs["aero_states"] == 28
    quasi = whirl.load(deck, set=sets, unsteady_aero=False).simulate(**run)
    assert quasi.attrs["aero_states"] == 0
    for flags, expected in (((), series), (("--quasi-steady-aero",), quasi)):
        out = tmp_path / str(len(flags))
        code, _, err = cli("simulate", deck, "--set", "RotSpeed=0", "--set", "BlPitch(1)=75", "--equilibrium",
                           "--init", "blade 1 flap 1+=0.1", "--tmax", 0.5, "--no-plot", "--out", out, *flags)
        assert code == 0, err
        csv = pd.read_csv(out / "timeseries.csv", index_col=0, float_precision="round_trip")
        np.testing.assert_array_equal(expected.to_numpy(), csv.to_numpy())
    # The states' loads move the flap differently from the quasi-steady loads [m, of the 0.1 m release].
    assert np.abs(series["blade 1 flap 1"] - quasi["blade 1 flap 1"]).max() > 1e-3
