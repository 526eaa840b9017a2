"""Model.closed_loop against `whirl campbell --closed-loop` (issue 43 from Python, issue 44): the same
tables to the last digit, and the errors with the CLI's text."""
import numpy as np
import pandas as pd
import pytest

import whirl

from conftest import case, cli, cli_error

DECK = case("nrel5mw", "Main_ROSCO.fst")


def test_closed_loop_equals_the_cli(tmp_path):
    result = whirl.load(DECK).closed_loop(wind=[10, 14], azimuths=6)
    code, _, err = cli("campbell", DECK, "--wind", "10:4:14", "--azimuths", 6, "--closed-loop", "--no-plot", "--out", tmp_path)
    assert code == 0, err
    read = lambda name: pd.read_csv(tmp_path / name, keep_default_na=False, na_values=["nan"], float_precision="round_trip")
    pd.testing.assert_frame_equal(result.modes, read("closed_loop_modes.csv"), check_exact=True)
    pd.testing.assert_frame_equal(result.margins, read("margins.csv"), check_exact=True)
    pd.testing.assert_frame_equal(result.campbell, read("campbell.csv"), check_exact=True)
    pd.testing.assert_frame_equal(result.open_loop_campbell, read("open_loop_campbell.csv"), check_exact=True)
    # 10 m/s: the torque PI acts, the pitch loop does not (NaN margins); 14 m/s: the pitch loop acts.
    assert result.margins["pitch_gain_margin"].isna().tolist() == [True, False]
    assert result.margins["stable"].tolist() == [1, 1]
    assert "controller: pitch PI integral" not in set(result.modes["mode"])


def test_closed_loop_needs_roscos_controller():
    with pytest.raises(whirl.InputError, match="closed_loop needs ROSCO's controller"):
        whirl.load(case("nrel5mw", "Main_Aero.fst")).closed_loop(wind=[12])


def test_simulate_with_rosco_equals_the_cli(tmp_path):
    table = whirl.load(DECK).simulate(tmax=3, wind=14, closed_loop=True, inputs={"wind speed": "step(1,0.2)"},
                                      plot=False)
    code, _, err = cli("simulate", DECK, "--wind", 14, "--closed-loop", "--tmax", 3, "--input", "wind speed=step(1,0.2)",
                       "--no-plot", "--out", tmp_path)
    assert code == 0, err
    ref = pd.read_csv(tmp_path / "timeseries.csv", index_col=0, float_precision="round_trip")
    np.testing.assert_array_equal(table.index.to_numpy(), ref.index.to_numpy())
    np.testing.assert_array_equal(table.to_numpy(), ref.to_numpy())  # the same bits
    assert table["GenSpeed [rad/s]"].iloc[-1] > table["GenSpeed [rad/s]"].iloc[0]  # the step speeds it up first
    with pytest.raises(whirl.InputError, match="closed_loop: needs wind="):
        whirl.load(DECK).simulate(tmax=1, closed_loop=True)


def test_closed_loop_step_equals_verify_closed_loop(tmp_path):
    # `whirl verify --closed-loop`'s closed_loop_step.csv to the last digit; the rise of the generator speed
    # agrees with the linear closed loop (tests/validation/test_closed_loop_simulation.cpp checks the numbers).
    table = whirl.load(DECK).closed_loop_step(wind=14, tmax=3, outputs=["GenSpeed"])
    code, _, err = cli("verify", DECK, "--closed-loop", "--wind", 14, "--tmax", 3, "--output", "GenSpeed", "--no-plot",
                       "--out", tmp_path)
    assert code == 0, err
    ref = pd.read_csv(tmp_path / "closed_loop_step.csv", float_precision="round_trip")
    pd.testing.assert_frame_equal(table, ref, check_exact=True)
    assert list(table.columns) == ["time_s", "wind_speed_m_s", "GenSpeed_nonlinear", "GenSpeed_linear",
                                   "collective_pitch_nonlinear", "collective_pitch_linear"]
    with pytest.raises(whirl.InputError, match="closed_loop_step needs ROSCO's controller"):
        whirl.load(case("nrel5mw", "Main_Aero.fst")).closed_loop_step(wind=14)
    with pytest.raises(whirl.InputError, match="Nope: the model has no output of this name"):
        whirl.load(DECK).closed_loop_step(wind=14, tmax=2, outputs=["Nope"])
