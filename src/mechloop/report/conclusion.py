"""The conclusion of the report: the output parameter's range and the extremes of its
derivatives, the check of the chain for a break, and for a model with bodies the peak
balancing load, the peak reaction, the reduced inertia, the efficiency and the flywheel —
every number with its unit in the display units (the same units as the CSV tables)."""

from __future__ import annotations

import numpy as np

from mechloop.dynamics.analysis import DynamicResults
from mechloop.dynamics.cycle_validity import cycle_breaks
from mechloop.report.breaks import break_lines
from mechloop.report.document import Paragraph
from mechloop.report.numbers import Shown
from mechloop.report.values import finite_span, peak, symbol
from mechloop.solve.results import Results


def parameter_units(results: Results, name: str) -> tuple[str, str, str]:
    """The table units of ``name``, its 1st and its 2nd derivative ('m', 'm/s',
    'm/s^2'; 'deg', 'rad/s', 'rad/s^2'; analogs 'm/rad', ...)."""
    d1, d2 = results.derivative_units()
    base = "m" if name[0] == "r" else "rad"
    return ("m" if name[0] == "r" else "deg"), f"{base}/{d1}", f"{base}/{d2}"


def kinematic_lines(results: Results, name: str, shown: Shown, w: dict[str, str]
                    ) -> list[Paragraph]:
    """The output parameter's range and its derivatives' extremes, then the breaks."""
    unit, unit1, unit2 = parameter_units(results, name)
    value = np.asarray(results.value(name), dtype=float)
    value = np.degrees(value) if name[0] in "ab" else value  # α, or a spatial β
    out = []
    span = finite_span(value)
    if span is not None:
        out.append(Paragraph(w["stroke"].format(
            name=symbol(name), value=shown.text(span[1] - span[0], unit),
            low=shown.text(span[0], unit, max(map(abs, span))),
            high=shown.text(span[1], unit, max(map(abs, span))))))
    for key, values, u in (("extreme_rate", results.rate(name), unit1),
                           ("extreme_accel", results.accel(name), unit2)):
        span = finite_span(values)
        if span is not None:
            scale = max(map(abs, span))
            out.append(Paragraph(w[key].format(name=symbol(name),
                                               low=shown.text(span[0], u, scale),
                                               high=shown.text(span[1], u, scale))))
    lines = break_lines(results, shown, w)
    if lines:
        out.append(Paragraph(w["breaks_intro"]))
        out += [Paragraph(line) for line in lines]
    else:
        out.append(Paragraph(w["no_breaks"]))
    return out


def dynamic_lines(dyn: DynamicResults, shown: Shown, w: dict[str, str]) -> list[Paragraph]:
    """Peak balancing loads and reaction, reduced inertia, efficiency and flywheel (or
    the warning that the cycle figures are not valid)."""
    out = []
    for k, values in dyn.forces.balancing.items():
        stem, unit = dyn.balancing_name(k)
        found = peak(values)
        if found is not None:
            out.append(Paragraph(w["peak_bal"].format(name=stem, value=shown.text(
                abs(found[1]), unit), position=found[0])))
    peaks = {n: peak(np.abs(r.force)) for n, r in dyn.forces.reactions.items()}
    peaks = {n: p for n, p in peaks.items() if p is not None}
    if peaks:
        joint = max(peaks, key=lambda n: peaks[n][1])
        position, value = peaks[joint]
        out.append(Paragraph(w["peak_reaction"].format(name=joint, value=shown.text(
            value, "N"), position=position)))
    if dyn.reduced is not None:
        linear = dyn.kinematics.argument_kinds[dyn.mechanism.drives[0].argument] == "length"
        out += reduced_range(linear, dyn.reduced.inertia, dyn.reduced.d_inertia, shown, w)
    broken = cycle_breaks(dyn)
    if broken is not None:
        out.append(Paragraph(w["cycle_breaks"].format(where=broken.where(shown.lang)),
                             "warning"))
        return out
    eta = np.nan if dyn.summary is None else float(np.ravel(dyn.summary.efficiency)[0])
    if dyn.summary is not None:
        out.append(Paragraph(w["no_efficiency"] if not np.isfinite(eta) else
                             w["efficiency"].format(value=f"{shown.number(100 * eta)} %")))
    cycle = dyn.cycle
    if cycle is not None and cycle.flywheel is not None:
        linear = dyn.kinematics.argument_kinds[dyn.mechanism.drives[0].argument] == "length"
        flywheel = float(np.ravel(cycle.flywheel)[0])
        out.append(Paragraph(w["flywheel"].format(
            delta=shown.number(float(cycle.delta)),
            value=shown.text(flywheel, "kg" if linear else "kg*m^2"))))
    return out


def conclusion_blocks(results: Results, dyn: DynamicResults | None, name: str,
                      shown: Shown, w: dict[str, str]) -> list[Paragraph]:
    """The paragraphs of the conclusion."""
    out = kinematic_lines(results, name, shown, w)
    if dyn is not None:
        out += dynamic_lines(dyn, shown, w)
    return out


def reduced_range(linear: bool, inertia: np.ndarray, slope: np.ndarray, shown: Shown,
                  w: dict[str, str]) -> list[Paragraph]:
    """The conclusion's sentence on the ranges of the reduced inertia (``m_red`` of a
    length input, else ``J_red``) and its derivative over the positions (arrays ``(P,)``,
    SI; NaN at broken positions); none when either has no finite value."""
    names = ("m_red", "dm_red") if linear else ("J_red", "dJ_red")
    units = ("kg", "kg/m") if linear else ("kg*m^2", "kg*m^2/rad")
    inertia, slope = finite_span(inertia), finite_span(slope)
    if inertia is None or slope is None:
        return []
    a, b = max(map(abs, inertia)), max(map(abs, slope))
    return [Paragraph(w["reduced_range"].format(
        name=names[0], low=shown.text(inertia[0], units[0], a),
        high=shown.text(inertia[1], units[0], a), dname=names[1],
        dlow=shown.text(slope[0], units[1], b), dhigh=shown.text(slope[1], units[1], b)))]
