"""Model.campbell and Model.modes against `whirl campbell` / `whirl modes`; progress, Ctrl-C,
the GIL released (two threads), the plot."""
import _thread
import threading
import time

import numpy as np
import pandas as pd
import pytest

import whirl
from conftest import case, cli


@pytest.fixture(scope="module")
def cli_campbell(tmp_path_factory):
    out = tmp_path_factory.mktemp("campbell")
    code, _, err = cli("campbell", case("nrel5mw", "Main_Onshore.fst"), "--rpm", "0:6:12", "--azimuths", 8,
                       "--no-plot", "--out", out)
    assert code == 0, err
    return pd.read_csv(out / "campbell.csv", float_precision="round_trip")


@pytest.fixture(scope="module")
def table(onshore):
    return onshore.campbell(rpm=[0, 6, 12], azimuths=8, participations=True)


def test_campbell_equals_the_cli_csv(cli_campbell, table):
    assert list(table["mode"]) == list(cli_campbell["mode"])
    for c in ("rpm", "freq_hz", "damping_ratio"):
        np.testing.assert_array_equal(table[c].to_numpy(), cli_campbell[c].to_numpy(), err_msg=c)  # same bits
    assert isinstance(table, whirl.CampbellTable) and isinstance(table.head(), whirl.CampbellTable)
    parts = table.filter(like="participation: ")
    np.testing.assert_allclose(parts.sum(axis=1), 1.0, rtol=1e-9)  # kinetic-energy shares sum to 1


def test_modes_equal_the_cli(onshore):
    path = case("nrel5mw", "Main_Onshore.fst")
    code, out, err = cli("modes", path, "--rpm", 6, "--azimuths", 8, "--format", "csv")
    assert code == 0, err
    import io
    expected = pd.read_csv(io.StringIO(out), float_precision="round_trip")
    got = onshore.modes(onshore.operating_point(rpm=6), azimuths=8)
    assert list(got["name"]) == list(expected["name"])
    for c in ("freq_hz", "damped_freq_hz", "damping_ratio"):
        np.testing.assert_array_equal(got[c].to_numpy(), expected[c].to_numpy(), err_msg=c)


def test_plot_has_two_panels(table):
    import matplotlib
    matplotlib.use("Agg")
    top, bottom = table.plot(max_freq=3.2)
    assert top.get_ylabel() == "Frequency [Hz]" and bottom.get_ylabel() == "Damping ratio [%]"
    assert len(top.lines) >= table["mode"].nunique()


def test_progress_callback_and_stop(onshore):
    calls = []
    onshore.campbell(rpm=[0, 6], azimuths=4, progress=lambda d, t: calls.append((d, t)))
    assert calls == [(1, 2), (2, 2)]

    def stop(done, total):
        raise RuntimeError("stop here")
    with pytest.raises(RuntimeError, match="stop here"):
        onshore.campbell(rpm=[0, 6, 12], azimuths=4, progress=stop)


def test_ctrl_c_stops_a_sweep(onshore):
    # interrupt_main is what Ctrl-C does to the main thread: a pending SIGINT, seen after the point
    # being computed. The first point's progress call interrupts; the sweep stops there.
    done = []

    def progress(d, total):
        done.append(d)
        if d == 1:
            _thread.interrupt_main()
    with pytest.raises(KeyboardInterrupt):
        onshore.campbell(rpm=list(range(0, 20)), azimuths=4, progress=progress)
    assert done == [1]  # stopped, not run to its end
    # The interpreter and the model are fine afterwards.
    assert len(onshore.campbell(rpm=[3], azimuths=4)) > 0


def test_two_threads_linearize_concurrently(onshore):
    # With the GIL released, Python runs while C++ computes: the main thread keeps ticking during one
    # long call of another thread (a single C++ call that held the GIL would leave it at 0 or 1 ticks
    # for its whole duration), and two threads linearizing at once get the same matrices.
    ticks, inside = [0], threading.Event()

    def long_call():
        inside.set()
        onshore.campbell(rpm=list(range(16)), azimuths=36)  # one C++ call, a quarter of a second here

    worker = threading.Thread(target=long_call)
    worker.start()
    inside.wait()
    start = time.monotonic()
    while worker.is_alive():
        ticks[0] += 1
        time.sleep(0.001)
    elapsed = time.monotonic() - start
    worker.join()
    assert ticks[0] > 10, (elapsed, ticks[0])

    results = {}

    def work(k):
        results[k] = onshore.linearize(onshore.operating_point(rpm=9), azimuths=12).A

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    np.testing.assert_array_equal(results[0], results[1])


def test_campbell_argument_errors(onshore):
    with pytest.raises(whirl.InputError, match="exactly one of"):
        onshore.campbell(rpm=[1], wind=[8])
    with pytest.raises(whirl.InputError, match="rpm: rotor speed must be finite"):
        onshore.operating_point(rpm=-1)


def test_schedule_dataframe_equals_the_schedule_file(onshore, tmp_path):
    # The first two rows of the NREL 5MW operating schedule (cases/nrel5mw/NREL5MW_Oper.csv), as a file
    # (the CLI's reader) and as a DataFrame read with pandas: the same points, the same numbers.
    table = pd.read_csv(case("nrel5mw", "NREL5MW_Oper.csv"), float_precision="round_trip").iloc[[4, 8]]
    path = tmp_path / "oper.csv"
    table.to_csv(path, index=False)
    from_file = onshore.campbell(schedule=str(path), azimuths=4)
    from_frame = onshore.campbell(schedule=table, azimuths=4)
    pd.testing.assert_frame_equal(from_file, from_frame, check_exact=True)
    assert from_frame["wind_speed"].tolist()[0] == table.iloc[0, 0]
    with pytest.raises(whirl.InputError, match="no rotor-speed column"):
        onshore.campbell(schedule=table.drop(columns=["RotSpeed_[rpm]"]), azimuths=4)
