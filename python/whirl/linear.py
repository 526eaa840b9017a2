"""Linear models: state space (A, B, C, D), the second-order matrices (M, damping, K, Q) and their
named states, inputs and outputs; conversions to xarray and scipy."""
from __future__ import annotations

from typing import List

import pandas as pd


class StateSpace:
    """ẋ = A x + B u, y = C x + D u about an operating point; x = [δq; δq̇; z] (coordinates, their rates,
    first-order states), units per variable in ``states``/``inputs``/``outputs`` (SI: m, rad, N, N m …).
    Arrays are read-only numpy views of the C++ result (no copy)."""

    def __init__(self, core):
        self._core = core

    A = property(lambda self: self._core.A, doc="state matrix (nx × nx)")
    B = property(lambda self: self._core.B, doc="input matrix (nx × nu)")
    C = property(lambda self: self._core.C, doc="output matrix (ny × nx)")
    D = property(lambda self: self._core.D, doc="feedthrough matrix (ny × nu)")
    xdot_op = property(lambda self: self._core.xdot_op, doc="ẋ at the operating point")
    multiblade = property(lambda self: self._core.multiblade,
                          doc="rotating entries in multiblade coordinates (the azimuth average)")
    azimuth = property(lambda self: self._core.azimuth, doc="azimuth of blade 1 [rad] (per-azimuth models)")
    rotor_speed = property(lambda self: self._core.rotor_speed, doc="rotor speed [rad/s]")

    @property
    def states(self) -> pd.DataFrame:
        """name, unit, operating value op, blade (0-based, -1 = fixed frame) of each state."""
        return pd.DataFrame(self._core.states(), columns=["name", "unit", "op", "blade"])

    @property
    def inputs(self) -> pd.DataFrame:
        """name, unit, operating value op, blade of each input."""
        return pd.DataFrame(self._core.inputs(), columns=["name", "unit", "op", "blade"])

    @property
    def outputs(self) -> pd.DataFrame:
        """name, unit, operating value op, blade of each output."""
        return pd.DataFrame(self._core.outputs(), columns=["name", "unit", "op", "blade"])

    state_names = property(lambda self: [s["name"] for s in self._core.states()], doc="state names, in order")
    input_names = property(lambda self: [s["name"] for s in self._core.inputs()], doc="input names, in order")
    output_names = property(lambda self: [s["name"] for s in self._core.outputs()], doc="output names, in order")

    def to_scipy(self):
        """A ``scipy.signal.StateSpace`` (continuous time) with copies of A, B, C, D."""
        from scipy import signal
        return signal.StateSpace(self.A.copy(), self.B.copy(), self.C.copy(), self.D.copy())

    def to_xarray(self):
        """An ``xarray.Dataset`` with A (state, state_from), B (state, input), C (output, state_from),
        D (output, input); coordinates are the names, with ``*_unit`` and ``*_op`` coordinates beside."""
        import xarray as xr
        s, u, y = self.states, self.inputs, self.outputs

        def coords(df, dim):
            return {dim: df["name"].to_numpy(), f"{dim}_unit": (dim, df["unit"].to_numpy()),
                    f"{dim}_op": (dim, df["op"].to_numpy())}
        c = {**coords(s, "state"), **coords(u, "input"), **coords(y, "output"), "state_from": s["name"].to_numpy()}
        return xr.Dataset({"A": (("state", "state_from"), self.A), "B": (("state", "input"), self.B),
                           "C": (("output", "state_from"), self.C), "D": (("output", "input"), self.D)},
                          coords=c)

    def __repr__(self) -> str:
        return f"<whirl.StateSpace {self.A.shape[0]} states, {self.B.shape[1]} inputs, {self.C.shape[0]} outputs>"


class ExportedModel(StateSpace):
    """The state-space model of one operating point of :meth:`whirl.Model.export` (one point of
    ``whirl export``'s files): ``A, B, C, D`` and the names of its .mat/.lin/.json files, the multiblade
    average over the azimuths for a turning rotor of 3+ blades, else the one model; ``per_azimuth``
    the rotating-frame models of the revolution (empty for a model without rotor)."""

    def __init__(self, core):
        super().__init__(core.state_space)
        self._lin = core

    rpm = property(lambda self: self._lin.rpm, doc="rotor speed [rpm]")
    wind_speed = property(lambda self: self._lin.wind_speed, doc="wind speed [m/s] or None")
    pitch_deg = property(lambda self: self._lin.pitch_deg, doc="collective pitch [deg] or None")

    @property
    def per_azimuth(self) -> List[StateSpace]:
        """The per-azimuth models (rotating frame), in azimuth order."""
        return [StateSpace(s) for s in self._lin.per_azimuth]

    def __repr__(self) -> str:
        return (f"<whirl.{type(self).__name__} at {self.rpm:g} rpm: {self.A.shape[0]} states, {self.B.shape[1]} "
                f"inputs, {self.C.shape[0]} outputs{', multiblade' if self.multiblade else ''}>")


class LinearModel(ExportedModel):
    """The linear models at one operating point (``Model.linearize``).

    ``A, B, C, D`` and the names are those of ``whirl export`` (its .mat file's A, B, C, D): the
    multiblade average over the azimuths for a turning rotor of 3+ blades, else the one model;
    ``per_azimuth`` the rotating-frame models of the revolution (empty for a model without rotor).
    ``M, damping, K, Q`` are the second-order model M δq̈ + damping δq̇ + K δq = Q δu of
    ``whirl linearize`` on the active coordinates ``dof_names`` at the equilibrium (the first
    azimuth's), SI units (kg, kg m², N/m, N m/rad …).
    """

    M = property(lambda self: self._lin.M, doc="mass matrix (n × n)")
    damping = property(lambda self: self._lin.damping, doc="damping matrix (n × n), the C of M q̈ + C q̇ + K q = Q u")
    K = property(lambda self: self._lin.K, doc="stiffness matrix (n × n)")
    Q = property(lambda self: self._lin.Q, doc="input matrix of the second-order model (n × nu)")
    dof_names = property(lambda self: list(self._lin.dof_names), doc="active coordinates of M, damping, K")
    compute_seconds = property(lambda self: self._lin.seconds,
                               doc="wall time of the C++ library's computation [s], the Python call around it "
                                   "excluded (python/bench/overhead.py measures the call's overhead with it)")
