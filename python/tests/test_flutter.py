"""Model.flutter: the search of `whirl flutter` (modal/flutter_search.hpp) from Python — the same rotor speeds,
least-damped modes and onset as the command's flutter.csv; progress and errors."""
import io

import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import case, cli

# The NREL 5MW with BeamDyn blades in still air (tests/cli/test_cli_flutter.cpp): a coarse FE blade (20
# elements, 6 modes) keeps the search to seconds; quasi-steady, its torsion mode flutters near 15 rpm.
DECK = case("nrel5mw_beamdyn", "Main_Aero_BD.fst")
SETS = {"CompServo": 0, "HWindSpeed": 0, "WakeMod": 0, "blade_elements": 20, "blade_modes": 6}
SEARCH = dict(rpm_min=10, rpm_max=40, rpm_step=2, tolerance=0.01, azimuths=8)


def test_search_equals_the_command(tmp_path):
    seen = []
    table = whirl.load(DECK, set=SETS).flutter(**SEARCH, progress=lambda rpm, d: seen.append((rpm, d)))
    args = [a for k, v in SETS.items() for a in ("--set", f"{k}={v}")]
    code, _, err = cli("flutter", DECK, *args, "--azimuths", 8, "--rpm-min", 10, "--rpm-max", 40, "--rpm-step", 2,
                       "--tolerance", 0.01, "--out", tmp_path)
    assert code == 0, err
    text = (tmp_path / "flutter.csv").read_text()
    rows, onset_line = text.split("# onset,")
    csv = pd.read_csv(io.StringIO(rows))
    assert list(table.columns) == list(csv.columns)
    assert list(table["least_damped_mode"]) == list(csv["least_damped_mode"])
    for column in ("rpm", "frequency_hz", "damping_ratio"):  # the file's 6 significant digits
        np.testing.assert_allclose(table[column], csv[column], rtol=5e-6, atol=1e-9)
    mode, freq, rpm = onset_line.strip().split(",")
    onset = table.attrs["onset"]
    assert onset["mode"] == mode
    assert onset["rpm"] == pytest.approx(float(rpm), rel=5e-6)
    assert onset["frequency_hz"] == pytest.approx(float(freq), rel=5e-6)
    # The onset lies in the final bracket: the last stable and unstable speeds evaluated.
    stable = table[table["damping_ratio"] >= 0]["rpm"].max()
    unstable = table[table["damping_ratio"] < 0]["rpm"].min()
    assert stable < onset["rpm"] < unstable and unstable - stable <= 0.01 + 1e-9
    assert [r for r, _ in seen] == list(table["rpm"])


def test_stable_up_to_the_last_speed_has_no_onset():
    table = whirl.load(DECK, set=SETS).flutter(rpm_min=10, rpm_max=12, rpm_step=2, azimuths=8)
    assert table.attrs["onset"] is None
    assert list(table["rpm"]) == [10, 12] and (table["damping_ratio"] > 0).all()


def test_errors_are_the_commands():
    model = whirl.load(DECK, set=SETS)
    with pytest.raises(whirl.InputError, match="flutter: the rotor speeds 20 to 10 rpm are not an increasing range"):
        model.flutter(rpm_min=20, rpm_max=10)
    with pytest.raises(whirl.InputError, match=r"flutter: rpm_step: 0 is outside \[0.001, 1000\] rpm"):
        model.flutter(rpm_min=10, rpm_max=12, rpm_step=0)
    tower = whirl.load(case("tower_topmass", "tower_topmass_fem.yaml"))
    with pytest.raises(whirl.InputError, match=r"flutter: the model has no rotor \(no rotating coordinate\)"):
        tower.flutter(rpm_min=1, rpm_max=2)


def test_progress_error_stops_the_search():
    def stop(rpm, damping):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        whirl.load(DECK, set=SETS).flutter(rpm_min=10, rpm_max=12, azimuths=8, progress=stop)
