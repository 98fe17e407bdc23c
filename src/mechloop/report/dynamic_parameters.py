"""Section 6 of the report, the mass characteristics, forces and moments: tables of the
bodies (m, J, centre), the kinematic pairs, the forces (magnitude, point, direction), the
moments, and gravity, springs, dampers and friction, in the display units."""

from __future__ import annotations

import numpy as np

from mechloop.dynamics.analysis import DynamicResults
from mechloop.model.dynamic import ExpressionValue, ParameterValue
from mechloop.model.indicator import IndicatorValue
from mechloop.model.schema import Model
from mechloop.model.units import to_si, unit_factor
from mechloop.report.document import Section, Table
from mechloop.report.numbers import Shown
from mechloop.report.values import angle_text, point_text, span_text, symbol


def body_table(dyn: DynamicResults, model: Model, shown: Shown, w: dict[str, str]
               ) -> Table:
    """Each lumped mass: body number, name, m, J about its centre, centre."""
    rows = []
    for mass in dyn.mechanism.masses:
        frame = dyn.mechanism.bodies[mass.body]
        inertia = np.asarray(mass.inertia, dtype=float)
        rows.append((str(mass.body), frame.name or "",
                     shown.number(shown.value(float(mass.mass), "kg")),
                     span_text(shown, inertia, "kg*m^2", bare=True)
                     if inertia.size > 1 else
                     shown.number(shown.value(float(inertia), "kg*m^2")),
                     point_text(mass.center, model, shown, w)))
    header = (w["h_number"], w["h_name"], f"m, {shown.unit_text('kg')}",
              f"J, {shown.unit_text('kg*m^2')}", w["h_centre"])
    return Table(w["t_bodies"], header, rows)


def pair_table(dyn: DynamicResults, model: Model, shown: Shown, w: dict[str, str]
               ) -> Table:
    """Each kinematic pair: name, kind, the two bodies, its point, the vector it slides
    along, the coefficient of friction."""
    rows = []
    for pair in dyn.mechanism.pairs:
        kind = w[pair.kind] + (w["inferred"] if pair.inferred else "")
        rows.append((pair.name, kind, f"{pair.bodies[0]}–{pair.bodies[1]}",
                     point_text(pair.at, model, shown, w),
                     str(pair.along) if pair.along else "—",
                     shown.number(float(pair.friction)) if pair.friction else "0"))
    header = (w["h_name"], w["h_kind"], w["h_bodies"], w["h_point"], w["h_along"],
              w["h_friction"])
    return Table(w["t_pairs"], header, rows)


def _value_text(value, magnitude: np.ndarray | None, unit: str, model_unit: str,
                shown: Shown, w: dict[str, str], kind: str) -> str:
    """A load's value in words with its magnitude (or its range over the positions)."""
    if isinstance(value, int | float | str):
        return w["v_constant"].format(value=shown.text(to_si(value, kind, model_unit),
                                                       unit))
    span = "—" if magnitude is None else span_text(shown, magnitude, unit)
    if isinstance(value, ParameterValue):
        return w["v_parameter"].format(name=symbol(value.of), span=span)
    if isinstance(value, ExpressionValue):
        return w["v_expression"].format(text=value.expression, span=span)
    if isinstance(value, IndicatorValue):
        return w["v_indicator"].format(piston=symbol(value.piston), span=span)
    return w["v_table"].format(span=span)


def _when(load, w: dict[str, str]) -> str:
    if load.when is None:
        return ""
    sign = w["grows"] if load.when.sign == "positive" else w["falls"]
    return w["v_when"].format(name=symbol(load.when.rate_of), sign=sign)


def force_table(dyn: DynamicResults, model: Model, shown: Shown, w: dict[str, str]
                ) -> Table:
    """Each force: name, body, magnitude (or its table's range), point, direction."""
    solved = {f.name: f for f in dyn.loads.forces}
    rows = []
    for i, force in enumerate(model.forces):
        name = force.name or f"F{i + 1}"
        found = solved.get(name)
        magnitude = None if found is None else np.abs(np.asarray(found.force))
        text = _value_text(force.value, magnitude, "N", model.units.force, shown, w,
                           "force") + _when(force, w)
        angle = angle_text(force.angle, model, shown)
        direction = (w["d_along"].format(v=force.along, angle=angle) if force.along
                     else w["d_absolute"].format(angle=angle))
        rows.append((name, str(force.body), text, point_text(force.at, model, shown, w),
                     direction))
    header = (w["h_name"], w["h_body"], w["h_magnitude"], w["h_point"], w["h_direction"])
    return Table(w["t_forces"], header, rows)


def moment_table(dyn: DynamicResults, model: Model, shown: Shown, w: dict[str, str]
                 ) -> Table:
    """Each moment: name, body, value (counter-clockwise positive)."""
    solved = {m.name: m for m in dyn.loads.moments}
    rows = []
    for i, moment in enumerate(model.moments):
        name = moment.name or f"M{i + 1}"
        found = solved.get(name)
        values = None if found is None else np.asarray(found.moment, dtype=float)
        rows.append((name, str(moment.body),
                     _value_text(moment.value, values, "N*m", model.units.moment, shown, w,
                                 "moment") + _when(moment, w)))
    return Table(w["t_moments"], (w["h_name"], w["h_body"], w["h_value"]), rows)


def other_table(model: Model, shown: Shown, w: dict[str, str]) -> Table | None:
    """Gravity, springs, dampers and the friction defaults; None when there is none."""
    units = model.units
    rows = []
    if model.gravity is not None:
        g = to_si(model.gravity.g, "acceleration", units.acceleration)
        rows.append((w["o_gravity"], w["o_gravity_v"].format(
            g=shown.text(g, "m/s^2"), angle=angle_text(model.gravity.angle, model, shown))))
    force, length = unit_factor(units.force, "force"), unit_factor(units.length, "length")
    for i, spring in enumerate(model.springs):
        a, b = spring.bodies
        if spring.table is not None:
            text = w["o_spring_table"].format(a=a, b=b, count=len(spring.table))
        else:
            text = w["o_spring_v"].format(
                a=a, b=b, k=shown.text(float(spring.stiffness) * force / length, "N/m"),
                l0=shown.text(float(spring.free_length) * length, "m"),
                p=shown.text(float(spring.preload) * force, "N"))
        rows.append((w["o_spring"].format(name=spring.name or i + 1), text))
    for i, damper in enumerate(model.dampers):
        a, b = damper.bodies
        if damper.table is not None:
            text = w["o_damper_table"].format(a=a, b=b, count=len(damper.table))
        elif damper.ends is None:
            moment = unit_factor(units.moment, "moment")
            text = w["o_damper_v"].format(a=a, b=b, c=shown.text(
                float(damper.coefficient) * moment, "N*m*s/rad"))
        else:
            text = w["o_damper_v"].format(a=a, b=b, c=shown.text(
                float(damper.coefficient) * force / length, "N*s/m"))
        rows.append((w["o_damper"].format(name=damper.name or i + 1), text))
    if model.friction.coefficient:
        rows.append((w["o_friction"], w["o_friction_v"].format(
            f=shown.number(float(model.friction.coefficient)))))
    if not rows:
        return None
    return Table(w["t_other"], (w["h_name"], w["h_value"]), rows)


def masses_section(dyn: DynamicResults, model: Model, shown: Shown, w: dict[str, str]
                   ) -> Section:
    """Section 6: the tables of the bodies, pairs and loads."""
    blocks = [body_table(dyn, model, shown, w), pair_table(dyn, model, shown, w)]
    if model.forces:
        blocks.append(force_table(dyn, model, shown, w))
    if model.moments:
        blocks.append(moment_table(dyn, model, shown, w))
    other = other_table(model, shown, w)
    if other is not None:
        blocks.append(other)
    return Section(w["s_masses"], [b for b in blocks if not isinstance(b, Table) or b.rows])
