"""whirl.load / whirl.from_dict: the models of the CLI's loader, their names and units, and the
CLI's messages for bad input."""
import json

import numpy as np
import pytest

import whirl
from conftest import case, cli_error


def test_yaml_case_dofs_inputs_outputs():
    m = whirl.load(case("landbased_2dof", "landbased_2dof.yaml"))
    # The case's two DOFs (cases/landbased_2dof/landbased_2dof.yaml header): tower fore-aft, azimuth.
    assert list(m.dofs["name"]) == ["tower FA 1", "azimuth"]
    assert set(m.dofs["unit"]) <= {"m", "rad"}
    assert m.name == "landbased_2dof"


def test_openfast_deck_with_set_overrides():
    full = whirl.load(case("nrel5mw", "Main_Onshore.fst"))
    fewer = whirl.load(case("nrel5mw", "Main_Onshore.fst"), set={"GenDOF": False})
    gen = full.dofs.set_index("name")
    # GenDOF = False freezes the generator (drivetrain) azimuth coordinate: fewer free DOFs.
    assert (~fewer.dofs["frozen"]).sum() < (~full.dofs["frozen"]).sum()
    assert "unit" in full.inputs.columns and len(full.outputs) > 0
    assert len(gen) == len(full.dofs)


def _numbers(v):
    """PyYAML reads YAML 1.1, where 6.1e11 (no sign in the exponent) is text; the case reader reads it
    as a number, as YAML 1.2 does."""
    if isinstance(v, dict):
        return {k: _numbers(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_numbers(x) for x in v]
    if isinstance(v, str):
        try:
            return float(v)
        except ValueError:
            return v
    return v


def test_dict_case_equals_file_case():
    import yaml  # Debian python3-yaml (a dependency of python3-xarray's stack); skip when absent
    path = case("landbased_2dof", "landbased_2dof.yaml")
    with open(path) as f:
        d = _numbers(yaml.safe_load(f))
    a = whirl.load(path).linearize()
    b = whirl.from_dict(d, folder=case("landbased_2dof")).linearize()
    # The same reader on the same data: the same bits.
    assert np.array_equal(a.A, b.A) and np.array_equal(a.M, b.M)
    # A study without files: the tower stiffness scaled in the dict changes the tower frequency.
    for key in ("EIy", "EIz"):
        d["bodies"][0]["properties"][key] = [4 * v for v in d["bodies"][0]["properties"][key]]
    stiff = whirl.from_dict(d, folder=case("landbased_2dof")).modes()
    soft = whirl.load(path).modes()
    # Four times the bending stiffness: about twice the frequency (gravity softens it a little).
    assert 1.9 < stiff["freq_hz"].max() / soft["freq_hz"].max() < 2.1


def test_unknown_key_in_set_has_the_cli_message(tmp_path):
    path = case("landbased_2dof", "landbased_2dof.yaml")
    expected = cli_error("modes", path, "--set", "gravty=9")
    with pytest.raises(whirl.InputError) as e:
        whirl.load(path, set={"gravty": 9})
    assert str(e.value) == expected
    assert isinstance(e.value, ValueError)


def test_missing_file_and_bad_yaml_have_the_cli_message(tmp_path):
    missing = str(tmp_path / "none.yaml")
    with pytest.raises(whirl.InputError) as e:
        whirl.load(missing)
    assert str(e.value) == cli_error("modes", missing)
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\nbodies:\n  - name: a\n    type: rigid\n    mass: abc\n")
    with pytest.raises(whirl.InputError) as e:
        whirl.load(str(bad))
    assert str(e.value) == cli_error("modes", str(bad))
    assert e.value.file == str(bad) and e.value.line == 5 and e.value.key != ""


def test_bad_openfast_value_has_the_cli_message():
    deck = case("nrel5mw", "Main_Onshore.fst")
    with pytest.raises(whirl.InputError) as e:
        whirl.load(deck, set={"TipRad": "abc"})
    assert str(e.value) == cli_error("modes", deck, "--set", "TipRad=abc")


def test_dict_errors_name_the_dict():
    with pytest.raises(whirl.InputError) as e:
        whirl.from_dict({"name": "x", "gravty": 9.81, "bodies": []})
    assert e.value.file == "<dict>" and e.value.key == "gravty"
    assert "unknown key 'gravty'" in str(e.value)


def test_error_attributes_parse():
    e = whirl.InputError("t.yaml:1: gravty: unknown key 'gravty' (allowed: name)")
    assert (e.file, e.line, e.key) == ("t.yaml", 1, "gravty")
    e = whirl.InputError("bad.dat:3: Mass: 'abc' is not a number")
    assert (e.file, e.line, e.key) == ("bad.dat", 3, "Mass")


def test_point_outside_the_range_of_validity_is_a_compute_error():
    # An absurd gravity (40 g; whirl reads at most 100 g) converges to a blade slope beyond the model's range
    # (linearize/point_validity.hpp: 0.511 rad against 0.5).
    path = case("nrel5mw", "Main_Onshore.fst")
    expected = cli_error("modes", path, "--set", "gravity=400", "--azimuths", 4)
    model = whirl.load(path, set={"gravity": 400})
    with pytest.raises(whirl.ComputeError) as e:
        model.modes(azimuths=4)
    # The CLI's message, its option named as the keyword argument.
    assert str(e.value) == expected.replace("--allow-invalid-point", "allow_invalid_point=True")
    assert isinstance(e.value, RuntimeError)
