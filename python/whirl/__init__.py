"""whirl: linearization and stability analysis of wind turbines, from Python.

The same C++ library as the ``whirl`` command line (docs/user/python.md): models are loaded from
YAML cases or OpenFAST decks, operating points solved, linearized and analysed in memory; results
come back as numpy arrays and pandas DataFrames with the columns of the CLI's files.

Units are SI unless a name says otherwise: rotor speed in rpm, pitch and azimuth in degrees,
frequencies in Hz, wind speed in m/s. Frames: OpenFAST's inertial frame for OpenFAST decks (x
downwind, z up), the case's ground frame for YAML cases (docs/architecture.md, *Notation*).

>>> import whirl
>>> model = whirl.load("cases/nrel5mw/Main_Onshore.fst", set={"GenDOF": False})
>>> model.campbell(rpm=[0, 6, 12]).head()
"""
from __future__ import annotations

import json
import os
import re
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _whirl
from ._tables import CampbellTable
from .linear import LinearModel, StateSpace
from . import lin


__version__ = getattr(_whirl, "__version__", "0")
__all__ = ["load", "from_dict", "Model", "OperatingPoint", "LinearModel", "StateSpace", "CampbellTable", "InputError", "lin",
           "ComputeError"]

#: Bad input: a file that is missing or malformed, an unknown key, a value out of range. The message
#: is the CLI's, ``file:line: key: reason``; the attributes ``file``, ``line`` (0 when unknown) and
#: ``key`` ("" when none) are parsed from it. A subclass of ValueError.
InputError = _whirl.InputError
#: A computation without a valid result (no equilibrium, singular matrix, point outside the model's
#: range of validity), with the CLI's message. A subclass of RuntimeError.
ComputeError = _whirl.ComputeError
#: A solved operating point (equilibrium): ``q``, ``qd`` (all coordinates, m or rad and their rates),
#: ``u`` (inputs, in their units), ``rpm``, ``wind_speed`` [m/s], ``pitch_deg``, ``iterations``,
#: ``residual_norm`` [N, N m].
OperatingPoint = _whirl.OperatingPoint

_WHERE = re.compile(r"^(?P<file>.*?):(?P<line>\d+): (?P<rest>.*)$", re.S)


def _where(message: str) -> tuple:
    """(file, line, key) of a ``file:line: key: reason`` message; parts not present are "" or 0."""
    m = _WHERE.match(message)
    if m:
        file, line, rest = m.group("file"), int(m.group("line")), m.group("rest")
    else:
        head, sep, rest = message.partition(": ")
        if not sep:
            return "", 0, ""
        file, line = head, 0
    key, sep, _ = rest.partition(": ")
    if not sep or " " in key or not key:
        key = ""
    return file, line, key


InputError.file = property(lambda self: _where(str(self))[0], doc="the input file named by the message")
InputError.line = property(lambda self: _where(str(self))[1], doc="1-based line in that file, 0 when unknown")
InputError.key = property(lambda self: _where(str(self))[2], doc="the key (dotted path, OpenFAST key), or ''")


def _sets(overrides: Optional[Mapping[str, Any]]) -> list:
    """The CLI's ``--set KEY=VALUE`` list of a dict; booleans as True/False (OpenFAST's spelling)."""
    out = []
    for key, value in (overrides or {}).items():
        if isinstance(value, (bool, np.bool_)):
            value = "True" if value else "False"
        out.append(f"{key}={value}")
    return out


def load(path: Union[str, os.PathLike, Mapping], set: Optional[Mapping[str, Any]] = None,
         allow_outside_files: bool = False) -> "Model":
    """Load a model, as every ``whirl`` command does with ``CASE --set KEY=VALUE``.

    Parameters
    ----------
    path : str, path or dict
        A YAML case file (``.yaml``, ``.yml``), an OpenFAST ``.fst`` or ElastoDyn ``.dat`` deck; a dict
        is a YAML case as data (see :func:`from_dict`).
    set : dict, optional
        Overrides applied before the model is built: ``{"GenDOF": False}`` (an OpenFAST key),
        ``{"bodies.tower.uniform.EIy": 1e11}`` (a dotted path of a YAML case), ``{"gravity": 0}``.
    allow_outside_files : bool
        Let a YAML case's ``file:`` entries name files outside the case's folder.

    Raises
    ------
    InputError
        With the CLI's ``file:line: key: reason`` message.
    """
    if isinstance(path, Mapping):
        return from_dict(path, set=set, allow_outside_files=allow_outside_files)
    return Model(_whirl.load(os.fspath(path), _sets(set), allow_outside_files))


def _plain(value):
    """A dict's values as JSON: numpy scalars and arrays as numbers and lists."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise TypeError(f"cannot write {type(value).__name__} in a case")


def from_dict(case: Mapping, folder: Union[str, os.PathLike] = ".", set: Optional[Mapping[str, Any]] = None,
              allow_outside_files: bool = False) -> "Model":
    """Build a model from a YAML case given as a dict (the schema of cases/README.md), no file written.

    ``folder`` is where the case's ``file:`` entries (property and shape tables) are looked up, as a
    case file's own folder. Messages name the case ``<dict>`` with the line of the key in the JSON
    text the dict is written as (one key per line).
    """
    text = json.dumps(case, indent=1, default=_plain)
    return Model(_whirl.load_text(text, os.fspath(folder), _sets(set), allow_outside_files))


def _progress(progress):
    """The sweep's progress callback: a callable (done, total), True for a tqdm bar (when tqdm is
    installed; otherwise a line on stderr), or None."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return progress
    try:
        from tqdm import tqdm  # optional
    except ImportError:
        import sys

        def line(done, total):
            print(f"\r{done}/{total} operating points", end="\n" if done == total else "", file=sys.stderr)
        return line
    bar = {}

    def update(done, total):
        if "bar" not in bar:
            bar["bar"] = tqdm(total=total, unit="point")
        bar["bar"].update(done - bar["bar"].n)
        if done == total:
            bar["bar"].close()
    return update


def _schedule_rows(table: pd.DataFrame) -> list:
    """(rpm, wind speed or None, pitch [deg] or None) per row of a schedule DataFrame, its columns found
    as ``readSchedule`` finds them in a CSV file (src/io/schedule.cpp)."""
    def find(match):
        return next((c for c in table.columns if match(str(c).lower())), None)
    rpm = find(lambda n: n.startswith("rotspeed")) or find(lambda n: n == "rpm" or n.startswith("rpm_"))
    if rpm is None:
        raise InputError("schedule: no rotor-speed column (a column named RotSpeed… or rpm)")
    wind = find(lambda n: n.startswith("ws") or n.startswith("wind"))
    pitch = find(lambda n: n.startswith("bldpitch") or n.startswith("pitch"))

    def value(row, col):
        return None if col is None or pd.isna(row[col]) else float(row[col])
    return [(float(row[rpm]), value(row, wind), value(row, pitch)) for _, row in table.iterrows()]


class Model:
    """A loaded model: coordinates (DOFs), inputs, outputs and bodies, and the analyses of the CLI.

    Immutable: a parameter study loads one model per value (:func:`load` with ``set=``, or
    :func:`from_dict`). Methods release the GIL while they compute, so threads run in parallel.
    """

    def __init__(self, core: "_whirl.Model"):
        self._core = core

    @property
    def name(self) -> str:
        """The model's name (the case's ``name``, or the ElastoDyn deck's title line)."""
        return self._core.name

    @property
    def source(self) -> str:
        """The case path, or ``<dict>``."""
        return self._core.source

    @property
    def notes(self) -> list:
        """The readers' informational lines (the CLI's ``whirl: note:``): inputs read and left out."""
        return list(self._core.notes)

    @property
    def dofs(self) -> pd.DataFrame:
        """Coordinates: name, unit (m or rad), body, kind (joint/elastic), frozen, rotating, blade
        (0-based, -1 = fixed frame), value [m or rad], rate [m/s or rad/s]."""
        return pd.DataFrame(self._core.dofs())

    @property
    def inputs(self) -> pd.DataFrame:
        """Inputs u: name, unit, operating value, blade."""
        return pd.DataFrame(self._core.inputs(), columns=["name", "unit", "value", "blade"])

    @property
    def outputs(self) -> pd.DataFrame:
        """Outputs y: name, unit, blade."""
        return pd.DataFrame(self._core.outputs(), columns=["name", "unit", "blade"])

    @property
    def bodies(self) -> pd.DataFrame:
        """Bodies: name and parent ("ground" for the root)."""
        return pd.DataFrame(self._core.bodies(), columns=["name", "parent"])

    def __repr__(self) -> str:
        return f"<whirl.Model {self.name!r} from {self.source!r}: {len(self._core.dofs())} DOFs>"

    def operating_point(self, rpm: Optional[float] = None, wind: Optional[float] = None,
                        pitch: Optional[float] = None, azimuth: Optional[float] = None) -> OperatingPoint:
        """Solve the equilibrium at an operating condition.

        rpm: rotor speed [rpm] (default: the model's); wind: hub-height wind speed [m/s]; pitch:
        collective blade pitch [deg], positive to feather; azimuth: rotor azimuth [deg] (0 = blade 1
        up for an OpenFAST turbine). Absent values keep the model's own.
        """
        return self._core.operating_point(rpm, wind, pitch, azimuth)

    def linearize(self, op: Optional[OperatingPoint] = None, azimuths: int = 36,
                  inputs: Sequence[str] = (), outputs: Sequence[str] = (), drop_azimuth: bool = False) -> LinearModel:
        """The linear model at ``op`` (default: the model's own condition), as ``whirl export`` computes it.

        A turning rotor is linearized at ``azimuths`` azimuths per revolution; with 3 or more blades
        ``A, B, C, D`` are the multiblade average (``per_azimuth`` keeps the rotating-frame models).
        ``inputs``/``outputs`` keep those, in that order; ``drop_azimuth`` removes the azimuth state.
        """
        return LinearModel(_whirl.linearize(self._core, op, azimuths, list(inputs), list(outputs), drop_azimuth))

    def steady(self, wind: Iterable[float], azimuths: int = 3) -> pd.DataFrame:
        """Trimmed steady operating points along the wind (``whirl steady --wind``): a DataFrame with
        the columns of steady.csv (wind_speed_m_s, rotor_speed_rpm, pitch_deg, aero_power_kw, …, region)."""
        return pd.DataFrame(_whirl.steady(self._core, [float(w) for w in np.atleast_1d(wind)], azimuths))

    def modes(self, op: Optional[OperatingPoint] = None, azimuths: int = 36,
              allow_invalid_point: bool = False) -> pd.DataFrame:
        """Modes at ``op`` (``whirl modes``, dense solver): index, name, freq_hz, damped_freq_hz,
        damping_ratio, rigid_body, first_order and one ``participation: <coordinate>`` column per
        coordinate (kinetic-energy share, rows sum to 1). Rotors: multiblade coordinates."""
        return pd.DataFrame(_whirl.modes(self._core, op, azimuths, allow_invalid_point))

    def campbell(self, rpm: Optional[Iterable[float]] = None, wind: Optional[Iterable[float]] = None,
                 schedule: Union[None, str, os.PathLike, pd.DataFrame] = None, azimuths: int = 36,
                 progress: Union[None, bool, Callable[[int, int], Any]] = None, participations: bool = False,
                 allow_invalid_point: bool = False) -> CampbellTable:
        """Campbell diagram (``whirl campbell``): give exactly one of

        - ``rpm``: rotor speeds [rpm];
        - ``wind``: wind speeds [m/s], each trimmed (rotor speed below rated, pitch above);
        - ``schedule``: a schedule CSV path, or a DataFrame with its columns (the CLI's rules: rotor
          speed ``RotSpeed…`` or ``rpm`` [rpm], optional wind speed ``WS…``/``wind…`` [m/s] and pitch
          ``BldPitch…``/``pitch…`` [deg], names in any case), e.g. an OpenFAST ``*_Oper.csv`` read with pandas.

        Returns a tidy :class:`CampbellTable`, one row per operating point and tracked mode (the
        rows of campbell.csv): point, rpm, wind_speed, pitch_deg, mode, freq_hz, damped_freq_hz,
        damping_ratio, stable, rigid_body, first_order (and ``participation: <coordinate>`` columns
        when ``participations``). ``.plot()`` draws the CLI's two panels.

        ``progress``: a callable (done, total) called after each point, or True for a tqdm bar.
        Ctrl-C (KeyboardInterrupt) or an exception of the callback stops the sweep after the point
        being computed, and is raised here.
        """
        if isinstance(schedule, pd.DataFrame):
            schedule = _schedule_rows(schedule)
        elif schedule is not None:
            schedule = os.fspath(schedule)
        def floats(v):
            return None if v is None else [float(x) for x in np.atleast_1d(v)]
        columns = _whirl.campbell(self._core, floats(rpm), floats(wind), schedule, azimuths, _progress(progress),
                                  participations, allow_invalid_point)
        table = CampbellTable(columns)
        table.attrs["versus"] = "wind" if rpm is None else "rpm"
        table.attrs["title"] = "Campbell diagram: " + (self.name.split(". ")[0] or self.source)
        return table
