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

import dataclasses
import io
import json
import os
import re
from typing import Any, Callable, Iterable, List, Mapping, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _whirl
from ._tables import BodeTable, CampbellTable
from .linear import ExportedModel, LinearModel, StateSpace
from . import lin


__version__ = getattr(_whirl, "__version__", "0")
__all__ = ["load", "from_dict", "compare", "Model", "OperatingPoint", "LinearModel", "ExportedModel", "StateSpace",
           "CampbellTable", "BodeTable", "ClosedLoop", "Verification", "InputError", "ComputeError", "lin"]

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
         allow_outside_files: bool = False, unsteady_aero: Optional[bool] = None) -> "Model":
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
    unsteady_aero : bool, optional
        The blade elements' unsteady-airfoil and dynamic-inflow states in the model's linearizations:
        ``None`` where the deck's AeroDyn asks for them (``UA_Mod`` 4 or 6, ``DBEMT_Mod`` 3), ``True``
        the same but an error on a deck without unsteady-airfoil states (the CLI's ``--unsteady-aero``),
        ``False`` quasi-steady: the static polar on the frozen wake (``--quasi-steady-aero``).

    Raises
    ------
    InputError
        With the CLI's ``file:line: key: reason`` message.
    """
    if isinstance(path, Mapping):
        return from_dict(path, set=set, allow_outside_files=allow_outside_files, unsteady_aero=unsteady_aero)
    return Model(_whirl.load(os.fspath(path), _sets(set), allow_outside_files, unsteady_aero))


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
              allow_outside_files: bool = False, unsteady_aero: Optional[bool] = None) -> "Model":
    """Build a model from a YAML case given as a dict (the schema of cases/README.md), no file written.

    ``folder`` is where the case's ``file:`` entries (property and shape tables) are looked up, as a
    case file's own folder. Messages name the case ``<dict>`` with the line of the key in the JSON
    text the dict is written as (one key per line).
    """
    text = json.dumps(case, indent=1, default=_plain)
    return Model(_whirl.load_text(text, os.fspath(folder), _sets(set), allow_outside_files, unsteady_aero))


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


def _floats(values) -> Optional[list]:
    """A number or a sequence of numbers as a list of floats; None stays None."""
    return None if values is None else [float(x) for x in np.atleast_1d(values)]


def _folder(out) -> Optional[str]:
    return None if out is None else os.fspath(out)


def _schedule_rows(table: pd.DataFrame) -> list:
    """(rpm, wind speed or None, pitch [deg] or None) per row of a schedule DataFrame, its columns found
    as ``readSchedule`` finds them in a CSV file (src/io/text/schedule.cpp)."""
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


@dataclasses.dataclass
class ClosedLoop:
    """Result of :meth:`Model.closed_loop`: the CLI's closed-loop tables as DataFrames."""
    modes: pd.DataFrame
    margins: pd.DataFrame
    campbell: pd.DataFrame
    open_loop_campbell: pd.DataFrame


@dataclasses.dataclass
class Verification:
    """Result of :meth:`Model.verify`: the linear model checked against the nonlinear equations.

    ``levels``: per amplitude ε, ε/2, … the largest difference between the nonlinear and the linear free decay
    (``max_difference``, m or rad), the linear response's largest deviation (``max_response``) and the observed
    order log2 of consecutive differences (``order``, ≥ 2 expected; NaN on the first row). ``identified``: per
    perturbed coordinate the damped frequency [Hz] and damping ratio identified from its decay, the pole realized
    from every state's response nearest the mode it moves most (``realized_*``), and that mode (``mode``,
    ``mode_damped_freq_hz``, ``mode_damping_ratio``). ``aero_states``: the aerodynamic states in both models.
    """
    levels: pd.DataFrame
    identified: pd.DataFrame
    aero_states: int


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

    def steady(self, wind: Iterable[float], azimuths: int = 3,
               progress: Union[None, bool, Callable[[int, int], Any]] = None) -> pd.DataFrame:
        """Trimmed steady operating points along the wind (``whirl steady --wind``): a DataFrame with
        the columns of steady.csv (wind_speed_m_s, rotor_speed_rpm, pitch_deg, aero_power_kw, …, region).

        wind: wind speeds [m/s], trimmed in order (each search started from its predecessors), with the
        deck's ROSCO controller when its ServoDyn file names one; azimuths: equilibria per torque
        evaluation over one blade passage. ``progress`` and Ctrl-C as :meth:`campbell` (per wind speed).
        """
        return pd.DataFrame(_whirl.steady(self._core, _floats(wind), azimuths, _progress(progress)))

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

        ``progress``: a callable (done, total) called after each point, or True for a tqdm bar (along
        the wind the trims count too: total is twice the number of wind speeds).
        Ctrl-C (KeyboardInterrupt) or an exception of the callback stops the sweep after the point
        being computed, and is raised here.
        """
        if isinstance(schedule, pd.DataFrame):
            schedule = _schedule_rows(schedule)
        elif schedule is not None:
            schedule = os.fspath(schedule)
        columns = _whirl.campbell(self._core, _floats(rpm), _floats(wind), schedule, azimuths, _progress(progress),
                                  participations, allow_invalid_point)
        table = CampbellTable(columns)
        table.attrs["versus"] = "wind" if rpm is None else "rpm"
        table.attrs["title"] = "Campbell diagram: " + (self.name.split(". ")[0] or self.source)
        return table

    def closed_loop(self, wind: Iterable[float], azimuths: int = 36, without_speed_filter: bool = False,
                    progress: Union[None, bool, Callable[[int, int], Any]] = None) -> "ClosedLoop":
        """The turbine with the deck's ROSCO controller in the loop along the wind (``whirl campbell
        --wind … --closed-loop``): each wind speed [m/s] trimmed where the controller settles, the
        open-loop plant (multiblade average over ``azimuths``, azimuth dropped) closed by the controller
        linearized there. ``without_speed_filter`` leaves the generator-speed low pass out.

        Returns a :class:`ClosedLoop` of DataFrames with the CLI's files' columns and numbers:
        ``modes`` (closed_loop_modes.csv: every root, open and closed loop, eigenvalue [1/s],
        controller share, unstable), ``margins`` (margins.csv: per wind speed and loop gain, phase and
        delay margins, peak sensitivity; NaN where a loop does not act), ``campbell`` and
        ``open_loop_campbell`` (the tracked lines, campbell.csv's columns).
        Raises :class:`InputError` for a deck without ROSCO's controller.
        """
        t = _whirl.closed_loop(self._core, _floats(wind), azimuths, without_speed_filter, _progress(progress))
        read = lambda text: pd.read_csv(io.StringIO(text), keep_default_na=False, na_values=["nan"],
                                        float_precision="round_trip")
        return ClosedLoop(read(t["modes"]), read(t["margins"]), read(t["campbell"]), read(t["open_loop_campbell"]))

    def closed_loop_step(self, wind: float, wind_step: float = 0.1, step_time: float = 1.0, tmax: float = 12.0,
                         dt_out: float = 0.05, controller_dt: float = 0.01, azimuths: int = 12,
                         outputs: Sequence[str] = ("GenSpeed", "TTDspFA")) -> pd.DataFrame:
        """The linear closed loop checked against the nonlinear turbine with its ROSCO controller
        (``whirl verify --closed-loop``): from the steady state at ``wind`` [m/s], a wind step
        ``wind_step`` [m/s] at ``step_time`` [s], simulated with ROSCO's discrete laws every
        ``controller_dt`` and by the linear closed loop (quasi-steady induction, multiblade average over
        ``azimuths``). Returns closed_loop_step.csv as a DataFrame: ``time_s``, ``wind_speed_m_s``, then
        per signal (``outputs`` and the pitch command) ``<name>_nonlinear`` and ``<name>_linear``, the
        changes from the steady values. Raises :class:`InputError` for a deck without ROSCO's controller.
        """
        text = _whirl.closed_loop_step(self._core, float(wind), float(wind_step), float(step_time), float(tmax),
                                       float(dt_out), float(controller_dt), int(azimuths), list(outputs))
        return pd.read_csv(io.StringIO(text), float_precision="round_trip")

    def verify(self, rpm: Optional[float] = None, dofs: Optional[Sequence[str]] = None, amplitude: float = 0.01,
               levels: int = 3, tmax: float = 10.0, dt_out: float = 0.01,
               allow_invalid_point: bool = False) -> Verification:
        """The linear model at the equilibrium checked against the nonlinear equations (``whirl verify``): free
        decays from the equilibrium at ``rpm`` [rpm] (default the model's) perturbed by ``amplitude`` [m or rad],
        halved ``levels`` times, along each of ``dofs`` (default every non-rotating active coordinate), simulated
        for ``tmax`` [s] sampled every ``dt_out`` [s] and against exp(A t) x0; with the model's unsteady-airfoil and
        dynamic-inflow states in both (as the load's ``unsteady_aero=`` chose). Only for time-invariant models
        (no turning bladed rotor). Returns a :class:`Verification`.
        """
        lv, identified, aero = _whirl.verify(self._core, rpm, list(dofs or []), float(amplitude), int(levels),
                                             float(tmax), float(dt_out), allow_invalid_point)
        return Verification(pd.DataFrame(lv), pd.DataFrame(identified), int(aero))

    def flutter(self, wind: float = 0.0, rpm_min: Optional[float] = None, rpm_max: Optional[float] = None,
                rpm_step: float = 1.0, tolerance: float = 0.01, min_freq: float = 0.1, azimuths: int = 36,
                allow_invalid_point: bool = False,
                progress: Optional[Callable[[float, float], Any]] = None) -> pd.DataFrame:
        """Flutter search (``whirl flutter``): the rotor speed raised from ``rpm_min`` [rpm] (default the
        deck's) in steps of ``rpm_step`` up to ``rpm_max`` (default 3 × the first) in still air or at ``wind``
        [m/s] with the pitch held, until the least-damped oscillating mode above ``min_freq`` [Hz] is
        unstable, then bisected to a bracket of ``tolerance`` [rpm]; each speed a multiblade average over
        ``azimuths``, with the model's aerodynamic states if it has them.

        Returns flutter.csv's rows as a DataFrame (``rpm``, ``least_damped_mode``, ``frequency_hz``,
        ``damping_ratio``, in the order evaluated); ``attrs["onset"]`` is ``{"rpm", "mode", "frequency_hz"}``
        (zero damping interpolated in the final bracket) or None when stable up to ``rpm_max``.
        ``progress(rpm, damping_ratio)`` is called after each rotor speed; Ctrl-C stops the search.
        """
        table, onset = _whirl.flutter(self._core, float(wind), rpm_min, rpm_max, float(rpm_step), float(tolerance),
                                      float(min_freq), int(azimuths), allow_invalid_point, progress)
        frame = pd.DataFrame(table)
        frame.attrs["onset"] = onset
        return frame

    def export(self, rpm: Union[None, float, Iterable[float]] = None, wind: Union[None, float, Iterable[float]] = None,
               schedule: Union[None, str, os.PathLike, pd.DataFrame] = None, azimuths: int = 36,
               inputs: Sequence[str] = (), outputs: Sequence[str] = (), drop_azimuth: bool = False,
               format: Optional[str] = None, out: Union[None, str, os.PathLike] = None,
               progress: Union[None, bool, Callable[[int, int], Any]] = None,
               allow_invalid_point: bool = False) -> List[ExportedModel]:
        """State-space models for controller design (``whirl export``), one per operating point.

        The points: ``rpm`` (rotor speeds [rpm]), ``wind`` (wind speeds [m/s], each trimmed as
        :meth:`steady`, with the deck's ROSCO controller when its ServoDyn file names one), or
        ``schedule`` (as :meth:`campbell`); at most one, none = the model's own condition. Each point
        starts from the model's initial point, so a point's model does not depend on its neighbours.
        ``azimuths`` per revolution, multiblade average for 3+ blades; ``inputs``/``outputs`` keep those,
        in that order (default all); ``drop_azimuth`` removes the azimuth state.

        Returns one :class:`ExportedModel` per point (``A, B, C, D`` in SI units with the names and
        units of the states, inputs and outputs; the equal of the files' matrices, bit for bit).
        Files only when asked: ``format`` ("mat", "lin" or "json") and ``out`` (a folder) together
        write ``whirl export``'s files there (all or none). ``progress`` and Ctrl-C as :meth:`campbell`.
        """
        if isinstance(schedule, pd.DataFrame):
            schedule = _schedule_rows(schedule)
        elif schedule is not None:
            schedule = os.fspath(schedule)
        points = _whirl.export(self._core, _floats(rpm), _floats(wind), schedule, azimuths, list(inputs), list(outputs),
                               drop_azimuth, _progress(progress), allow_invalid_point, format, _folder(out))
        return [ExportedModel(p) for p in points]

    def bode(self, inputs: Sequence[str], outputs: Sequence[str], rpm: Optional[float] = None,
             wind: Optional[float] = None, f_from: float = 0.01, f_to: float = 10.0, points: int = 400,
             azimuths: int = 36, out: Union[None, str, os.PathLike] = None, plot: bool = True,
             allow_invalid_point: bool = False) -> BodeTable:
        """Frequency response G(j 2π f) = C (j 2π f I − A)⁻¹ B + D of the linear model (``whirl bode``).

        The model: at ``rpm`` [rpm] (default: the model's own), or trimmed at ``wind`` [m/s]
        (aerodynamic models), multiblade average over ``azimuths`` without the azimuth state (a pure
        integrator of the rotor speed). ``inputs`` and ``outputs`` name the pairs (e.g.
        ``["collective pitch"]``, ``["GenSpeed"]``); ``points`` frequencies log-spaced from ``f_from``
        to ``f_to`` [Hz].

        Returns a :class:`BodeTable` indexed by ``freq_hz`` with bode.csv's columns
        ``"Y / U dB"`` (20 log10 ``|G|``, G in SI units) and ``"Y / U deg"`` (phase in (−180°, 180°]) —
        the same numbers as bode.csv; ``attrs["static_gain"]`` holds the signed static gains G(0) the
        CLI prints. ``out``: write bode.csv, bode.gp (and bode.png/svg when ``plot`` and Gnuplot is
        installed) into that folder.
        """
        f, names, values, gain, title = _whirl.bode(self._core, list(inputs), list(outputs), rpm, wind, f_from, f_to,
                                                    points, azimuths, allow_invalid_point, _folder(out), plot)
        table = BodeTable(np.asarray(values), index=pd.Index(f, name="freq_hz"), columns=names)
        table.attrs["static_gain"] = dict(gain)
        table.attrs["title"] = title
        return table

    def simulate(self, tmax: float, rpm: Optional[float] = None, dt_out: float = 0.01,
                 init: Optional[Mapping[str, float]] = None, inputs: Optional[Mapping[str, str]] = None,
                 drives: Optional[Mapping[str, str]] = None, free_rotor: bool = False, equilibrium: bool = False,
                 rtol: float = 1e-6, atol: float = 1e-8, out: Union[None, str, os.PathLike] = None,
                 plot: Union[bool, Sequence[str]] = True, progress: Optional[Callable[[float, float], Any]] = None,
                 allow_invalid_point: bool = False, wind: Optional[float] = None, closed_loop: bool = False,
                 controller_dt: float = 0.01) -> pd.DataFrame:
        """Integrate the nonlinear equations in time (``whirl simulate``: SUNDIALS IDA, AD Jacobians).

        Starts from the model's initial point (at ``rpm`` [rpm] when given), or its equilibrium
        (``equilibrium=True``), then ``init``: ``{"tower FA 1": 0.1}`` sets a coordinate [m or rad],
        ``{"tower FA 1+": 0.1}`` offsets it from the start, ``{"tower FA 1 rate": 0.5}`` sets its rate
        [m/s or rad/s]. ``inputs``: input histories added to the input's value, ``{"NAME": "step(t0,a)"}``,
        ``"ramp(t0,t1,a)"``, ``"sin(A,f)"`` or a CSV path (columns time, value); ``drives``: prescribed
        motions of coordinates (``"spinup(T,w)"`` or any input signal). The rotor turns at constant
        speed unless ``free_rotor``. ``rtol``/``atol``: IDA's tolerances [m, rad, m/s, rad/s];
        ``dt_out`` [s]: interval of the recorded instants up to ``tmax`` [s].

        Returns a DataFrame indexed by time [s] (``time_s``) with timeseries.csv's columns: each
        coordinate ``NAME`` and ``NAME rate``, each input ``input: NAME``, each output ``NAME [unit]``
        (the same numbers as the file); ``attrs``: IDA's statistics, ``states`` (the integrated
        coordinates) and ``aero_states`` (how many unsteady-airfoil and dynamic-inflow states were integrated
        with them: those of the model, as ``whirl.load(..., unsteady_aero=)`` chose). A motion leaving the model's range of validity raises ComputeError unless
        ``allow_invalid_point`` (then ``attrs["warning"]`` says where). ``out``: write timeseries.csv,
        timeseries.gp (and the images when ``plot`` and Gnuplot is installed; a list of column names
        for ``plot`` chooses the panels). ``progress(t, tmax)`` is called after each recorded instant;
        Ctrl-C stops the integration there (KeyboardInterrupt).

        ``wind`` [m/s]: start at the steady state trimmed there (with the deck's ROSCO controller when
        it names one), the rotor free (``--wind``); ``closed_loop``: ROSCO's controller in the loop,
        setting generator torque and collective pitch every ``controller_dt`` [s] (``--closed-loop``).
        """
        channels = [] if isinstance(plot, bool) else list(plot)
        names, values, stats, warning = _whirl.simulate(
            self._core, float(tmax), rpm, dt_out, [(k, float(v)) for k, v in (init or {}).items()],
            list((inputs or {}).items()), list((drives or {}).items()), free_rotor, equilibrium, rtol, atol,
            allow_invalid_point, _folder(out), channels, bool(plot), progress, wind, closed_loop, controller_dt)
        table = pd.DataFrame(np.asarray(values)[:, 1:], index=pd.Index(np.asarray(values)[:, 0], name=names[0]),
                             columns=names[1:])
        table.attrs.update(dict(stats))
        if warning:
            table.attrs["warning"] = warning
        return table


def compare(result: Union[str, os.PathLike, pd.DataFrame], reference: Union[str, os.PathLike, pd.DataFrame],
            tol_rel: float = 0.01, rpm: Optional[float] = None) -> pd.DataFrame:
    """Modes compared with a reference table (``whirl compare``).

    ``result``: a modes table (:meth:`Model.modes`, or a CSV of ``whirl modes``) or a Campbell table
    (:meth:`Model.campbell`, campbell.csv) with ``rpm`` [rpm] choosing its operating point;
    ``reference``: a CSV path or DataFrame with columns ``mode``, ``freq_hz`` [Hz] and optionally
    ``whirl_mode`` (the whirl name; ``a|b`` compares the rows sharing it as a set, ``*`` takes the
    nearest frequency), e.g. cases/nrel5mw/table9_1.csv [Jonkman2009, Table 9-1].

    Returns one row per reference mode: reference_mode, reference_freq_hz, whirl_mode, freq_hz,
    rel_error ((f − f_ref)/f_ref) and status ("ok", "FAIL" beyond ``tol_rel``, "MISSING"); the CLI
    exits with an error when a row is not "ok", this returns the table (check ``status``).
    """
    def rows(table, name_columns, with_whirl):
        name = next((c for c in name_columns if c in table.columns), None)
        if name is None or "freq_hz" not in table.columns:
            raise InputError(f"compare: a table needs columns {' or '.join(name_columns)} and freq_hz")
        if with_whirl:
            key = table["whirl_mode"] if "whirl_mode" in table.columns else table[name]
            return [(str(m), float(f), str(k)) for m, f, k in zip(table[name], table["freq_hz"], key)]
        return [(str(m), float(f)) for m, f in zip(table[name], table["freq_hz"])]

    if isinstance(result, pd.DataFrame):
        if "rpm" in result.columns:
            if rpm is None:
                raise InputError("compare: a Campbell table; choose the operating point with rpm=")
            result = result[(result["rpm"] - rpm).abs() <= 1e-9]  # the command's rule (modal/mode_compare.cpp)
        result = rows(result, ("name", "mode"), False)
    else:
        result = os.fspath(result)
    if isinstance(reference, pd.DataFrame):
        reference = rows(reference, ("mode",), True)
    else:
        reference = os.fspath(reference)
    return pd.DataFrame(_whirl.compare(result, reference, tol_rel, rpm))
