"""Model.verify: the check of `whirl verify` from Python (modal/nonlinear_check.hpp) — the same amplitudes,
differences, observed orders and identified frequencies as the command prints; errors by argument name."""
import math

import pytest

import whirl
from conftest import case, cli

LANDBASED = case("landbased_2dof", "landbased_2dof.yaml")


def _cli_tables(out):
    """The command's two tables: rows of the levels (amplitude, difference, response[, order]) and of the
    identified coordinates (coordinate, f, zeta, realized f, zeta, mode, mode f, zeta)."""
    lines = out.splitlines()
    start = next(i for i, l in enumerate(lines) if l.strip().startswith("amplitude")) + 1
    stop = next(i for i, l in enumerate(lines) if l.startswith("identified"))
    levels = [[float(x) for x in l.split()] for l in lines[start:stop]]
    identified = []
    for l in lines[stop + 2:]:
        left, middle, right = l.split("|")
        name, f, z = left.rsplit(None, 2)
        mode, fm, zm = right.rsplit(None, 2)
        identified.append((name.strip(), float(f), float(z), *map(float, middle.split()), mode.strip(), float(fm),
                           float(zm)))
    return levels, identified


def test_check_equals_the_command():
    code, out, err = cli("verify", LANDBASED)
    assert code == 0, err
    levels, identified = _cli_tables(out)
    v = whirl.load(LANDBASED).verify()
    assert v.aero_states == 0
    assert list(v.levels.columns) == ["amplitude", "max_difference", "max_response", "order"]
    assert len(v.levels) == len(levels) == 3
    for row, printed in zip(v.levels.itertuples(index=False), levels):
        assert row.amplitude == pytest.approx(printed[0], rel=1e-6)
        assert row.max_difference == pytest.approx(printed[1], rel=1e-5)
        assert row.max_response == pytest.approx(printed[2], rel=1e-5)
        if len(printed) == 4:
            assert row.order == pytest.approx(printed[3], abs=1e-3)
            assert row.order > 1.9  # the exported A is the Jacobian: the difference falls as ε²
        else:
            assert math.isnan(row.order)
    assert len(v.identified) == len(identified) == 1
    r, p = v.identified.iloc[0], identified[0]
    assert r["coordinate"] == p[0] == "tower FA 1" and r["mode"] == p[5] == "tower FA 1"
    # The command prints frequencies to 6 significant digits, damping ratios to 5.
    for column, printed, rel in zip(["damped_freq_hz", "damping_ratio", "realized_freq_hz", "realized_damping_ratio",
                                     "mode_damped_freq_hz", "mode_damping_ratio"], p[1:5] + p[6:8],
                                    [1e-5, 6e-5, 1e-5, 6e-5, 1e-5, 6e-5]):
        assert r[column] == pytest.approx(printed, rel=rel), column


def test_errors_name_the_argument():
    model = whirl.load(LANDBASED)
    with pytest.raises(whirl.InputError, match="dofs: 'nope': no such coordinate"):
        model.verify(dofs=["nope"])
    with pytest.raises(whirl.InputError, match=r"verify: levels: must lie in \[2, 8\]"):
        model.verify(levels=1)
    with pytest.raises(whirl.InputError, match="verify: amplitude: must be a positive number"):
        model.verify(amplitude=float("nan"))
    # limits::kMaxVerifyAmplitude: a perturbation in the linear range
    with pytest.raises(whirl.InputError, match=r"verify: amplitude: must be a positive number of at most 1 \(m or rad"):
        model.verify(amplitude=16.0)
    with pytest.raises(whirl.InputError, match="turning bladed rotor|periodic"):
        whirl.load(case("nrel5mw", "Main_Onshore.fst")).verify(tmax=1)
