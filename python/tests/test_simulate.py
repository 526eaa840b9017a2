"""Model.simulate: the time series of `whirl simulate` (same inputs, same code path: timeseries.csv's
numbers, bit for bit) as a DataFrame indexed by time; files only when asked; progress and Ctrl-C."""
import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import case, cli

ONSHORE = case("nrel5mw", "Main_Onshore.fst")


def read_series(path):
    return pd.read_csv(path, index_col=0, float_precision="round_trip")


def test_nrel5mw_step_equals_timeseries_csv(onshore, tmp_path):
    code, _, err = cli("simulate", ONSHORE, "--rpm", 12, "--tmax", 0.3, "--equilibrium", "--input",
                       "generator torque=step(0.1,1000)", "--init", "tower FA 1+=0.01", "--out", tmp_path, "--no-plot")
    assert code == 0, err
    series = onshore.simulate(0.3, rpm=12, equilibrium=True, inputs={"generator torque": "step(0.1,1000)"},
                              init={"tower FA 1+": 0.01})
    csv = read_series(tmp_path / "timeseries.csv")
    assert series.index.name == "time_s" and list(series.columns) == list(csv.columns)
    np.testing.assert_array_equal(series.index.to_numpy(), csv.index.to_numpy())
    np.testing.assert_array_equal(series.to_numpy(), csv.to_numpy())  # the same bits
    assert series.attrs["steps"] > 0 and "tower FA 1" in series.attrs["states"]


def test_files_only_when_asked(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    model = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    series = model.simulate(1.0, init={"tower FA 1": 0.1})
    assert list(tmp_path.iterdir()) == []
    assert series["tower FA 1"].iloc[0] == 0.1 and series.index[-1] == pytest.approx(1.0)
    model.simulate(1.0, init={"tower FA 1": 0.1}, out=tmp_path / "out", plot=False)
    np.testing.assert_array_equal(read_series(tmp_path / "out" / "timeseries.csv").to_numpy(), series.to_numpy())


def test_errors_name_the_argument():
    model = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    with pytest.raises(whirl.InputError, match="init: 'nope': no such coordinate \\(active: tower FA 1"):
        model.simulate(0.1, init={"nope": 1})
    with pytest.raises(whirl.InputError, match="inputs: 'thrust': no such input \\(inputs: none\\)"):
        model.simulate(0.1, inputs={"thrust": "step(0,1)"})
    with pytest.raises(whirl.InputError, match="drives: 'nope': no such active coordinate"):
        model.simulate(0.1, drives={"nope": "spinup(1,1)"})


def test_progress_and_interrupt():
    model = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    seen = []
    model.simulate(0.5, dt_out=0.1, init={"tower FA 1": 0.1}, progress=lambda t, end: seen.append((t, end)))
    assert seen[-1] == (pytest.approx(0.5), 0.5)

    def interrupt(t, end):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        model.simulate(0.5, init={"tower FA 1": 0.1}, progress=interrupt)


def test_time_and_signal_messages():
    model = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    with pytest.raises(whirl.InputError, match="tmax: simulated time must be positive"):
        model.simulate(0)
    onshore = whirl.load(ONSHORE)
    with pytest.raises(whirl.InputError, match="inputs generator torque: "):  # parseTimeSignal names the input
        onshore.simulate(0.1, inputs={"generator torque": "stepp(0,1)"})


def test_diverging_motion_is_an_error_unless_allowed(tmp_path):
    """A tower displaced far beyond the model's range of validity, as CliSimulate's test: ComputeError,
    nothing written; allowed, the series comes back with the warning."""
    model = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    with pytest.raises(whirl.ComputeError, match="leaves the model's range of validity"):
        model.simulate(0.1, init={"tower FA 1": 100}, out=tmp_path / "out")
    assert not (tmp_path / "out").exists()
    series = model.simulate(0.1, init={"tower FA 1": 100}, allow_invalid_point=True)
    assert "range of validity" in series.attrs["warning"]
