"""OpenFAST ``.lin`` files (``whirl lin``): modes of linearizations made by OpenFAST."""
from __future__ import annotations

import os
from typing import Iterable, Union

from . import _whirl
from ._tables import CampbellTable


def read(files: Union[str, os.PathLike, Iterable[Union[str, os.PathLike]]], participations: bool = False) -> CampbellTable:
    """Modes of a set of OpenFAST ``.lin`` files, as ``whirl lin`` computes them.

    The files are grouped by operating point (rotor speed, wind speed); each group's azimuths are
    transformed to multiblade coordinates [Bir2008] and averaged, the modes named from participation
    factors and tracked over the points. Returns a :class:`whirl.CampbellTable` (the columns of
    ``Model.campbell``); ``attrs["notes"]`` holds the transform's notes (the CLI's ``whirl: note:``).
    Raises :class:`whirl.InputError` with the CLI's message for a missing or malformed file.
    """
    if isinstance(files, (str, os.PathLike)):
        files = [files]
    columns, notes = _whirl.lin_campbell([os.fspath(f) for f in files], participations)
    table = CampbellTable(columns)
    table.attrs["versus"] = "rpm"
    table.attrs["title"] = "Campbell diagram: OpenFAST linearization"
    table.attrs["notes"] = list(notes)
    return table
