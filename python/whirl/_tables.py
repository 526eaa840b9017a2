"""Tables of results with their plots: the Campbell table (tidy, one row per point and mode)."""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np
import pandas as pd


class CampbellTable(pd.DataFrame):
    """A Campbell diagram as a tidy DataFrame (the rows of campbell.csv and more columns, see
    :meth:`whirl.Model.campbell`); ``attrs["versus"]`` is "rpm" or "wind", the default x axis."""

    @property
    def _constructor(self):
        return CampbellTable

    def plot(self, versus: Optional[str] = None, harmonics: Sequence[int] = (1, 3, 6, 9),
             max_freq: Optional[float] = None, first_order_lines: bool = False, ax=None):
        """The CLI's Campbell figure (campbell.gp): frequency [Hz] on top, damping ratio [%] below,
        one line per tracked mode, the nP excitation lines (grey, dashed) on the frequency panel.

        versus: "rpm" or "wind" (default: ``attrs["versus"]``); max_freq: top of the frequency axis
        [Hz] (default: automatic); first_order_lines: also the lines carried by first-order states
        (HydroDyn radiation), left out by default as in the CLI; ax: two matplotlib axes to draw in.
        Returns the two axes.
        """
        import matplotlib.pyplot as plt

        versus = versus or self.attrs.get("versus", "rpm")
        x = "wind_speed" if versus == "wind" else "rpm"
        if ax is None:
            fig, ax = plt.subplots(2, 1, sharex=True, figsize=(10, 8))
            fig.suptitle(self.attrs.get("title", "Campbell diagram"))
        top, bottom = ax
        for name, line in self.groupby("mode", sort=False):
            if not first_order_lines and "first_order" in line and line["first_order"].all():
                continue
            line = line.sort_values("point")
            if max_freq is not None and (line["freq_hz"] > max_freq).all():
                continue
            top.plot(line[x], line["freq_hz"], marker=".", label=name)
            bottom.plot(line[x], 100 * line["damping_ratio"], marker=".", label=name)
        points = self.drop_duplicates("point").sort_values("point")
        for n in harmonics:
            top.plot(points[x], n * points["rpm"] / 60.0, color="grey", linestyle="--", linewidth=0.8)
            if len(points):
                top.annotate(f"{n}P", (points[x].iloc[-1], n * points["rpm"].iloc[-1] / 60.0), color="grey")
        top.set_ylabel("Frequency [Hz]")
        top.set_ylim(0, max_freq if max_freq else 1.05 * float(np.nanmax(self["freq_hz"])) if len(self) else 1)
        bottom.set_ylabel("Damping ratio [%]")
        bottom.set_xlabel("Wind speed [m/s]" if versus == "wind" else "Rotor speed [rpm]")
        top.grid(True)
        bottom.grid(True)
        top.legend(fontsize="small", ncol=2, loc="upper left")
        return top, bottom


class BodeTable(pd.DataFrame):
    """A frequency response as a DataFrame indexed by ``freq_hz`` [Hz] with the columns of bode.csv:
    ``"Y / U dB"`` and ``"Y / U deg"`` per output/input pair (see :meth:`whirl.Model.bode`)."""

    @property
    def _constructor(self):
        return BodeTable

    def plot(self, ax=None):
        """The CLI's Bode figure (bode.gp): magnitude [dB] above, phase [deg] below, log frequency axis.
        ax: two matplotlib axes to draw in. Returns the two axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            fig, ax = plt.subplots(2, 1, sharex=True, figsize=(10, 7))
            fig.suptitle(self.attrs.get("title", "Frequency response"))
        top, bottom = ax
        for column in self.columns:
            if column.endswith(" dB"):
                top.semilogx(self.index, self[column], label=column[:-3])
            elif column.endswith(" deg"):
                bottom.semilogx(self.index, self[column])
        top.set_ylabel("Magnitude [dB of SI units]")
        bottom.set_ylabel("Phase [deg]")
        bottom.set_xlabel("Frequency [Hz]")
        top.grid(True, which="both")
        bottom.grid(True, which="both")
        top.legend(fontsize="small")
        return top, bottom
