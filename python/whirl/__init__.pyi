# Type stub of the whirl package (editors' completion; the documented implementation is __init__.py).
import os
from typing import Any, Callable, Iterable, List, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt
import pandas as pd

__version__: str

class InputError(ValueError):
    @property
    def file(self) -> str: ...
    @property
    def line(self) -> int: ...
    @property
    def key(self) -> str: ...

class ComputeError(RuntimeError): ...

class OperatingPoint:
    rpm: float
    wind_speed: Optional[float]
    pitch_deg: Optional[float]
    @property
    def q(self) -> npt.NDArray[np.float64]: ...
    @property
    def qd(self) -> npt.NDArray[np.float64]: ...
    @property
    def u(self) -> npt.NDArray[np.float64]: ...
    @property
    def iterations(self) -> int: ...
    @property
    def residual_norm(self) -> float: ...

class StateSpace:
    A: npt.NDArray[np.float64]
    B: npt.NDArray[np.float64]
    C: npt.NDArray[np.float64]
    D: npt.NDArray[np.float64]
    xdot_op: npt.NDArray[np.float64]
    multiblade: bool
    azimuth: float
    rotor_speed: float
    states: pd.DataFrame
    inputs: pd.DataFrame
    outputs: pd.DataFrame
    state_names: List[str]
    input_names: List[str]
    output_names: List[str]
    def to_scipy(self) -> Any: ...
    def to_xarray(self) -> Any: ...

class ExportedModel(StateSpace):
    rpm: float
    wind_speed: Optional[float]
    pitch_deg: Optional[float]
    per_azimuth: List[StateSpace]

class LinearModel(ExportedModel):
    M: npt.NDArray[np.float64]
    damping: npt.NDArray[np.float64]
    K: npt.NDArray[np.float64]
    Q: npt.NDArray[np.float64]
    dof_names: List[str]
    compute_seconds: float

class CampbellTable(pd.DataFrame):
    def plot(self, versus: Optional[str] = ..., harmonics: Sequence[int] = ..., max_freq: Optional[float] = ...,
             first_order_lines: bool = ..., ax: Any = ...) -> Any: ...

class BodeTable(pd.DataFrame):
    def plot(self, ax: Any = ...) -> Any: ...

class ClosedLoop:
    modes: pd.DataFrame
    margins: pd.DataFrame
    campbell: pd.DataFrame
    open_loop_campbell: pd.DataFrame
    def __init__(self, modes: pd.DataFrame, margins: pd.DataFrame, campbell: pd.DataFrame,
                 open_loop_campbell: pd.DataFrame) -> None: ...

class Verification:
    levels: pd.DataFrame
    identified: pd.DataFrame
    aero_states: int
    def __init__(self, levels: pd.DataFrame, identified: pd.DataFrame, aero_states: int) -> None: ...

class Model:
    name: str
    source: str
    notes: List[str]
    dofs: pd.DataFrame
    inputs: pd.DataFrame
    outputs: pd.DataFrame
    bodies: pd.DataFrame
    def operating_point(self, rpm: Optional[float] = ..., wind: Optional[float] = ..., pitch: Optional[float] = ...,
                        azimuth: Optional[float] = ...) -> OperatingPoint: ...
    def linearize(self, op: Optional[OperatingPoint] = ..., azimuths: int = ..., inputs: Sequence[str] = ...,
                  outputs: Sequence[str] = ..., drop_azimuth: bool = ...) -> LinearModel: ...
    def steady(self, wind: Iterable[float], azimuths: int = ...,
               progress: Union[None, bool, Callable[[int, int], Any]] = ...) -> pd.DataFrame: ...
    def modes(self, op: Optional[OperatingPoint] = ..., azimuths: int = ...,
              allow_invalid_point: bool = ...) -> pd.DataFrame: ...
    def campbell(self, rpm: Optional[Iterable[float]] = ..., wind: Optional[Iterable[float]] = ...,
                 schedule: Union[None, str, os.PathLike, pd.DataFrame] = ..., azimuths: int = ...,
                 progress: Union[None, bool, Callable[[int, int], Any]] = ..., participations: bool = ...,
                 allow_invalid_point: bool = ...) -> CampbellTable: ...
    def closed_loop(self, wind: Iterable[float], azimuths: int = ..., without_speed_filter: bool = ...,
                    progress: Union[None, bool, Callable[[int, int], Any]] = ...) -> ClosedLoop: ...
    def verify(self, rpm: Optional[float] = ..., dofs: Optional[Sequence[str]] = ..., amplitude: float = ...,
               levels: int = ..., tmax: float = ..., dt_out: float = ...,
               allow_invalid_point: bool = ...) -> Verification: ...
    def flutter(self, wind: float = ..., rpm_min: Optional[float] = ..., rpm_max: Optional[float] = ...,
                rpm_step: float = ..., tolerance: float = ..., min_freq: float = ..., azimuths: int = ...,
                allow_invalid_point: bool = ...,
                progress: Optional[Callable[[float, float], Any]] = ...) -> pd.DataFrame: ...
    def closed_loop_step(self, wind: float, wind_step: float = ..., step_time: float = ..., tmax: float = ...,
                         dt_out: float = ..., controller_dt: float = ..., azimuths: int = ...,
                         outputs: Sequence[str] = ...) -> pd.DataFrame: ...
    def export(self, rpm: Union[None, float, Iterable[float]] = ..., wind: Union[None, float, Iterable[float]] = ...,
               schedule: Union[None, str, os.PathLike, pd.DataFrame] = ..., azimuths: int = ...,
               inputs: Sequence[str] = ..., outputs: Sequence[str] = ..., drop_azimuth: bool = ...,
               format: Optional[str] = ..., out: Union[None, str, os.PathLike] = ...,
               progress: Union[None, bool, Callable[[int, int], Any]] = ...,
               allow_invalid_point: bool = ...) -> List[ExportedModel]: ...
    def bode(self, inputs: Sequence[str], outputs: Sequence[str], rpm: Optional[float] = ...,
             wind: Optional[float] = ..., f_from: float = ..., f_to: float = ..., points: int = ...,
             azimuths: int = ..., out: Union[None, str, os.PathLike] = ..., plot: bool = ...,
             allow_invalid_point: bool = ...) -> BodeTable: ...
    def simulate(self, tmax: float, rpm: Optional[float] = ..., dt_out: float = ...,
                 init: Optional[Mapping[str, float]] = ..., inputs: Optional[Mapping[str, str]] = ...,
                 drives: Optional[Mapping[str, str]] = ..., free_rotor: bool = ..., equilibrium: bool = ...,
                 rtol: float = ..., atol: float = ..., out: Union[None, str, os.PathLike] = ...,
                 plot: Union[bool, Sequence[str]] = ..., progress: Optional[Callable[[float, float], Any]] = ...,
                 allow_invalid_point: bool = ..., wind: Optional[float] = ...,
                 closed_loop: bool = ..., controller_dt: float = ...) -> pd.DataFrame: ...

def load(path: Union[str, os.PathLike, Mapping[str, Any]], set: Optional[Mapping[str, Any]] = ...,
         allow_outside_files: bool = ..., unsteady_aero: Optional[bool] = ...) -> Model: ...
def from_dict(case: Mapping[str, Any], folder: Union[str, os.PathLike] = ..., set: Optional[Mapping[str, Any]] = ...,
              allow_outside_files: bool = ..., unsteady_aero: Optional[bool] = ...) -> Model: ...
def compare(result: Union[str, os.PathLike, pd.DataFrame], reference: Union[str, os.PathLike, pd.DataFrame],
            tol_rel: float = ..., rpm: Optional[float] = ...) -> pd.DataFrame: ...
