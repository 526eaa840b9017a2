"""Model.linearize: the matrices of `whirl export --format mat` (same inputs, same code path: the
same bits), views without copies, names and units, xarray and scipy conversions."""
import numpy as np
import pytest

import whirl
from conftest import case, cli


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The CLI's statespace.mat for the NREL 5MW onshore deck at 12 rpm, 8 azimuths."""
    scipy_io = pytest.importorskip("scipy.io")
    out = tmp_path_factory.mktemp("export")
    code, _, err = cli("export", case("nrel5mw", "Main_Onshore.fst"), "--rpm", 12, "--azimuths", 8,
                       "--format", "mat", "--out", out)
    assert code == 0, err
    return scipy_io.loadmat(str(out / "statespace.mat"))


@pytest.fixture(scope="module")
def lin(onshore):
    return onshore.linearize(onshore.operating_point(rpm=12), azimuths=8)


def test_matrices_equal_the_cli_mat_file(exported, lin):
    for name in "ABCD":
        # one layout for one or many points, ROSCO's: 1 x n cells (docs/user/export-formats.md)
        np.testing.assert_array_equal(getattr(lin, name), exported[name][0][0], err_msg=name)  # bit for bit
    assert lin.multiblade
    names = [str(n[0]) if np.ndim(n) else str(n) for n in np.ravel(exported["x_names"])]
    assert [n.strip() for n in names] == lin.state_names


def test_arrays_are_views_without_copies(lin):
    a = lin.A
    assert not a.flags.owndata and not a.flags.writeable  # a view of the C++ result
    assert a.flags.f_contiguous  # Eigen's column-major storage
    assert np.shares_memory(a, lin.A)


def test_second_order_and_names(lin):
    n = len(lin.dof_names)
    assert lin.M.shape == lin.K.shape == lin.damping.shape == (n, n)
    # M symmetric positive definite (kinetic energy) [BranlardGeisler2022, eq. 25].
    np.testing.assert_allclose(lin.M, lin.M.T, rtol=1e-9, atol=1e-9 * np.abs(lin.M).max())
    assert np.all(np.linalg.eigvalsh(0.5 * (lin.M + lin.M.T)) > 0)
    assert set(lin.states["unit"]) <= {"m", "rad", "m/s", "rad/s"}
    assert len(lin.per_azimuth) == 8 and not lin.per_azimuth[0].multiblade


def test_to_scipy_and_xarray(lin):
    sys = lin.to_scipy()
    np.testing.assert_array_equal(sys.A, lin.A)
    ds = lin.to_xarray()
    assert list(ds["A"].coords["state"].values) == lin.state_names
    assert ds["B"].dims == ("state", "input")
    first = lin.output_names[0]
    np.testing.assert_array_equal(ds["C"].sel(output=first).values, lin.C[0])


def test_structural_model_second_order_equals_cli_linearize(tmp_path):
    path = case("landbased_2dof", "landbased_2dof.yaml")
    code, _, err = cli("linearize", path, "--out", tmp_path)
    assert code == 0, err
    import pandas as pd
    lin = whirl.load(path).linearize()
    for name, value in (("M", lin.M), ("K", lin.K), ("C", lin.damping)):
        csv = pd.read_csv(tmp_path / f"{name}.csv", index_col=0, float_precision="round_trip")
        # The CLI writes at full precision (round trip): equal numbers.
        np.testing.assert_array_equal(csv.to_numpy(), value, err_msg=name)


def test_unknown_input_is_an_input_error(onshore):
    with pytest.raises(whirl.InputError, match="unknown input 'nope'"):
        onshore.linearize(inputs=["nope"], azimuths=4)
