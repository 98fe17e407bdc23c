"""Indicator diagrams of a model's gas forces: p–V (the ideal diagram and the model's
positions on it) and p–φ over the crank's angle, one row per indicator load; and the
table of the diagrams over the positions."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from mechloop.engines.diagram import curve, stroke_names
from mechloop.views.figure import new_figure

if TYPE_CHECKING:
    from mechloop.dynamics.indicator import Indicator

CM3, MPA = 1e-6, 1e6


def plot_indicators(indicators: list[Indicator], *, title: str = "") -> Figure:
    """p–V and p–φ of every indicator load (pressures in MPa, volumes in cm³, angles in
    degrees)."""
    figure = new_figure(11.0, 4.0 * len(indicators))
    axes = figure.subplots(len(indicators), 2, squeeze=False)
    for (pv, pphi), item in zip(axes, indicators, strict=True):
        gas = item.gas
        names = stroke_names(item.cycle)
        v, p, s = curve(item.cycle, float(gas.swept))
        closed = np.append(np.arange(v.size), 0)  # the jumps between strokes drawn too
        pv.plot(v[closed] / CM3, p[closed] / MPA, color="0.6", linewidth=0.8)
        for k, name in enumerate(names):
            sel = s == k
            pv.plot(v[sel] / CM3, p[sel] / MPA, label=name)
        pv.plot(gas.volume / CM3, gas.pressure / MPA, "k.", markersize=3,
                label="model positions")
        pv.set_xlabel("V [cm³]")
        pv.set_ylabel("p [MPa]")
        pv.set_title(f"{item.name}: p–V, ∮p dV = {item.loop_work:.6g} J")
        pv.legend(fontsize="small")
        pv.grid(True, alpha=0.3)
        deg = np.degrees(item.angle)
        pphi.plot(deg, gas.pressure / MPA, "-", color="C0")
        pphi.set_xlabel("crank angle [deg]")
        pphi.set_ylabel("p [MPa]")
        pphi.set_title(f"{item.name}: p–φ")
        pphi.grid(True, alpha=0.3)
        force = pphi.twinx()
        force.plot(deg, gas.force / 1e3, "--", color="C3", linewidth=0.8)
        force.set_ylabel("gas force [kN]", color="C3")
    if title:
        figure.suptitle(title)
    return figure


def indicator_frame(indicators: list[Indicator]) -> pd.DataFrame:
    """One row per position: the crank's angle, then for each indicator load its stroke,
    volume, pressure and force (SI but the angle in degrees)."""
    first = indicators[0]
    columns: dict[str, object] = {"position": np.arange(first.angle.size),
                                  "crank angle [deg]": np.degrees(first.angle)}
    for item in indicators:
        names = np.array(stroke_names(item.cycle))
        columns[f"{item.name}: stroke"] = names[item.gas.stroke]
        columns[f"{item.name}: V [m^3]"] = item.gas.volume
        columns[f"{item.name}: p [Pa]"] = item.gas.pressure
        columns[f"{item.name}: F [N]"] = item.gas.force
    return pd.DataFrame(columns)
