"""Model.export: the points and files of `whirl export` (same inputs, same code path: the same bits);
files only when asked."""
import json

import numpy as np
import pytest

import whirl
from conftest import case, cli

ONSHORE = case("nrel5mw", "Main_Onshore.fst")


@pytest.fixture(scope="module")
def schedule(tmp_path_factory):
    """A schedule of two rotor speeds and pitches (the columns of OpenFAST's *_Oper.csv)."""
    path = tmp_path_factory.mktemp("schedule") / "schedule.csv"
    path.write_text("RotSpeed,BldPitch\n6,0\n12,2\n")
    return str(path)


@pytest.fixture(scope="module")
def cli_json(tmp_path_factory, schedule):
    """The CLI's statespace.json for the schedule on the NREL 5MW onshore deck, 4 azimuths."""
    out = tmp_path_factory.mktemp("export_cli")
    code, _, err = cli("export", ONSHORE, "--schedule", schedule,
                       "--azimuths", 4, "--format", "json", "--out", out, "--inputs", "generator torque,collective pitch")
    assert code == 0, err
    return out / "statespace.json"


def test_schedule_points_equal_the_cli_files(onshore, cli_json, schedule, tmp_path):
    points = onshore.export(schedule=schedule, azimuths=4,
                            inputs=["generator torque", "collective pitch"])
    data = json.loads(cli_json.read_text())
    assert len(points) == len(data["operating_points"]) == 2
    for p, d in zip(points, data["operating_points"]):
        d = d["model"]
        for name in "ABCD":
            # JSON numbers at full precision (shortest round trip): equal bits
            np.testing.assert_array_equal(getattr(p, name), np.array(d[name], dtype=float).reshape(getattr(p, name).shape),
                                          err_msg=name)
        assert p.input_names == ["generator torque", "collective pitch"]
    # The same files when asked: byte for byte.
    onshore.export(schedule=schedule, azimuths=4,
                   inputs=["generator torque", "collective pitch"], format="json", out=tmp_path)
    assert (tmp_path / "statespace.json").read_bytes() == cli_json.read_bytes()


def test_rpm_points_equal_linearize_and_write_nothing(onshore, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    points = onshore.export(rpm=[6, 12], azimuths=4)
    assert [p.rpm for p in points] == [6, 12]
    lin = onshore.linearize(onshore.operating_point(rpm=12), azimuths=4)
    np.testing.assert_array_equal(points[1].A, lin.A)  # exportSweep both: the same bits
    assert len(points[1].per_azimuth) == 4 and points[1].multiblade
    assert list(tmp_path.iterdir()) == []  # no format/out: no file


def test_progress_and_bad_arguments(onshore):
    seen = []
    onshore.export(rpm=[3, 6], azimuths=2, progress=lambda done, total: seen.append((done, total)))
    assert seen[-1] == (2, 2)
    with pytest.raises(whirl.InputError, match="at most one of"):
        onshore.export(rpm=[6], wind=[8])
    with pytest.raises(whirl.InputError, match="format: must be mat, lin or json"):
        onshore.export(rpm=[6], format="csv", out=".")
    with pytest.raises(whirl.InputError, match="unknown output 'nope'"):
        onshore.export(rpm=[6], azimuths=2, outputs=["nope"])


def test_progress_exception_stops_the_sweep(onshore):
    calls = []

    def stop(done, total):
        calls.append(done)
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        onshore.export(rpm=[3, 6, 9], azimuths=2, progress=stop)
    assert calls == [1]


def test_files_need_format_and_folder(onshore, tmp_path):
    with pytest.raises(whirl.InputError, match="give format= and out= together"):
        onshore.export(rpm=[6], format="mat")
    with pytest.raises(whirl.InputError, match="give format= and out= together"):
        onshore.export(rpm=[6], out=tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_wind_point_equals_the_cli_files(tmp_path):
    """`whirl export --wind` (trimmed with the deck's ROSCO controller, warm-started from the trim):
    the same bits from Model.export(wind=…)."""
    deck = case("nrel5mw", "Main_ROSCO.fst")
    code, _, err = cli("export", deck, "--wind", "12:1:12", "--azimuths", 4, "--format", "json", "--out", tmp_path,
                       "--inputs", "wind speed,collective pitch", "--outputs", "GenSpeed", "--drop-azimuth")
    assert code == 0, err
    (point,) = whirl.load(deck).export(wind=[12], azimuths=4, inputs=["wind speed", "collective pitch"],
                                       outputs=["GenSpeed"], drop_azimuth=True)
    d = json.loads((tmp_path / "statespace.json").read_text())["operating_points"][0]
    assert point.rpm == d["rpm"] and point.pitch_deg == d["pitch_deg"] and point.wind_speed == 12
    for name in "ABCD":
        np.testing.assert_array_equal(getattr(point, name), np.array(d["model"][name], dtype=float), err_msg=name)
