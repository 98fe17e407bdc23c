"""The joint reactions in the report of a model with spatial contours and ``joints:``
(issue 17), from :attr:`mechloop.spatial.dynamics.SpatialDynamics.reactions`
(:class:`~mechloop.spatial.reactions.SpatialReactions`), in the planar report's form
(its section 'Reactions in the kinematic pairs'):

* what the force analysis solved (bodies, equations, unknowns, rank), the joints' table
  (name, type, bodies, point, axis, the reaction's components), the idle motions whose
  equations were dropped and the positions where the force system is singular, in words;
* the magnitudes of every joint's force (and moment) over the positions
  (:func:`mechloop.views.spatial_reactions.plot_spatial_reactions`);
* per joint a table of its force ``R_x, R_y, R_z, |R|`` and, for a joint with a moment,
  ``R_mx, R_my, R_mz, |R_m|`` at :func:`table_positions` (every position is in the
  appendix), and the hodograph of its force in 3-D with the projections
  (:func:`mechloop.views.spatial_reactions.plot_spatial_hodograph`);
* the balancing load by the reactions' equations beside the one by virtual power and how
  closely they agree (:func:`agreement_lines`), and the conclusion's peak reaction
  (:func:`reaction_lines`).

Every number is in the display's force, moment and length units and precision
(:class:`~mechloop.report.numbers.Shown`); each table's forces to the precision of its
largest force, its moments to that of its largest moment.
"""

from __future__ import annotations

import re

import numpy as np
from numpy.typing import NDArray

from mechloop.model.schema import Model
from mechloop.output.display import TableDisplay
from mechloop.report.document import FigureItem, Paragraph, Section, Table
from mechloop.report.numbers import Shown
from mechloop.report.values import peak, point_text
from mechloop.solve.results import compress_positions
from mechloop.spatial.dynamics import SpatialDynamics
from mechloop.spatial.joints import COMPONENTS
from mechloop.spatial.reactions import JointReaction, SpatialReactions
from mechloop.views.display import Display
from mechloop.views.russian import translate

Array = NDArray[np.float64]

#: Rows of a joint's table at most (the positions spread over the cycle, the scheme's
#: position added): the classic twelve positions of a crank and the closing one.
TABLE_ROWS = 13
#: Components of each part of a joint's reaction by its type (force, moment): ``"xyz"``
#: three, ``"across"`` two across the axis.
_COUNT = {"xyz": 3, "across": 2, "": 0}
#: Significant digits of the difference of the two balancing loads.
AGREEMENT_DIGITS = 2
#: An idle motion as :func:`mechloop.spatial.determinacy.idle_motions` describes it.
_IDLE = re.compile(r"body (\d+): (turn about|slide along) \(([^)]*)\) at position (\d+)"
                   r"(?: \(the line of joints (.*)\))?")


def table_positions(count: int, position: int) -> list[int]:
    """The positions of a joint's table: every one of ``count`` up to
    :data:`TABLE_ROWS`, else :data:`TABLE_ROWS` spread evenly from the first to the last,
    with the scheme's ``position``."""
    if count <= TABLE_ROWS:
        return list(range(count))
    spread = np.unique(np.round(np.linspace(0, count - 1, TABLE_ROWS)).astype(int))
    return sorted({*(int(p) for p in spread), int(position)})


def _has_moment(reaction: JointReaction) -> bool:
    return bool(COMPONENTS[reaction.joint.kind][1])


def _body(body: int, w: dict[str, str], key: str) -> str:
    """Body ``body`` in words ('body 2', 'the ground'), ``key`` the grammatical form."""
    return w[f"{key}_ground"] if body == 0 else w[key].format(n=body)


def _direction(values, shown: Shown, w: dict[str, str]) -> str:
    v = np.asarray(values, dtype=float)
    x, y, z = (shown.number(c, 1.0) for c in v / np.linalg.norm(v))
    return w["d_vector"].format(x=x, y=y, z=z)


def pairs_table3(reactions: SpatialReactions, model: Model, shown: Shown,
                 w: dict[str, str]) -> Table:
    """Each joint: name, type, bodies (first–second), point, axis (along a vector, or
    its fixed direction), and the number of its force and moment components."""
    rows = []
    for name, reaction in reactions.joints.items():
        joint = reaction.joint
        if joint.axis is None:
            axis = w["none"]
        elif isinstance(joint.axis, int):
            axis = w["d_along3"].format(v=joint.axis)
        else:
            axis = _direction(joint.axis, shown, w)
        force, moment = (_COUNT[c] for c in COMPONENTS[joint.kind])
        rows.append((name, w[joint.kind], f"{joint.bodies[0]}–{joint.bodies[1]}",
                     point_text(joint.at, model, shown, w), axis, f"{force}; {moment}"))
    header = (w["h_name"], w["h_kind"], w["h_bodies"], w["h_point"], w["h_axis3"],
              w["h_components"])
    return Table(w["t_pairs3"], header, rows)


def reaction_table(name: str, reaction: JointReaction, positions: list[int],
                   shown: Shown, w: dict[str, str]) -> Table:
    """The reaction of joint ``name`` at ``positions``: its force's components and
    magnitude and, for a joint with a moment, its moment's ('—' where it is not known)."""
    parts = [("R", reaction.force, "N")]
    if _has_moment(reaction):
        parts.append(("R_m", reaction.moment, "N*m"))
    columns: list[list[str]] = []
    header: list[str] = [w["h_position"]]
    for symbol, values, unit in parts:
        at = shown.value(np.asarray(values, dtype=float)[:, positions], unit)
        block = np.vstack([at, np.linalg.norm(at, axis=0)])
        finite = block[np.isfinite(block)]
        scale = float(np.abs(finite).max()) if finite.size else 0.0
        columns += [[shown.number(v, scale) for v in row] for row in block]
        text = shown.unit_text(unit)
        sub = "" if symbol == "R" else "m"
        header += [f"R_{sub}{axis}, {text}" for axis in "xyz"]
        header.append(f"|{symbol}|, {text}")
    rows = [(str(p), *(c[k] for c in columns)) for k, p in enumerate(positions)]
    first, second = reaction.joint.bodies
    caption = w["t_reaction3"].format(name=name, a=_body(first, w, "of_body"),
                                      b=_body(second, w, "on_body"))
    return Table(caption, tuple(header), rows)


def idle_text(description: str, shown: Shown, w: dict[str, str]) -> str:
    """An idle motion of :func:`mechloop.spatial.determinacy.idle_motions` in the
    report's words and numbers (the text itself when it has another form)."""
    match = _IDLE.fullmatch(description)
    if match is None:
        return description
    body, how, axis, position, joints = match.groups()
    x, y, z = (shown.number(float(c), 1.0) for c in axis.split(","))
    axis_text = w["d_vector"].format(x=x, y=y, z=z)
    text = w["idle_turn" if how == "turn about" else "idle_slide"].format(
        body=body, axis=axis_text, position=position)
    return text + (w["idle_line"].format(joints=joints) if joints else "")


def solved_paragraph(dyn: SpatialDynamics, reactions: SpatialReactions,
                     w: dict[str, str]) -> Paragraph:
    """What the force analysis solved: bodies, equations, unknowns and the rank."""
    bodies = len(dyn.mechanism.bodies)
    return Paragraph(w["p_reactions3"].format(bodies=bodies, equations=6 * bodies,
                                              unknowns=reactions.unknowns,
                                              rank=reactions.rank))


def state_paragraphs(dyn: SpatialDynamics, reactions: SpatialReactions, shown: Shown,
                     w: dict[str, str]) -> list[Paragraph]:
    """The idle motions whose equations were dropped, and where the force system is
    singular (or that it is regular wherever the chain assembles)."""
    out = []
    if reactions.idle:
        out.append(Paragraph(w["p_idle"].format(
            count=len(reactions.idle),
            list="; ".join(idle_text(d, shown, w) for d in reactions.idle))))
    else:
        out.append(Paragraph(w["p_no_idle"]))
    singular = np.flatnonzero(reactions.singular)
    if singular.size:
        out.append(Paragraph(w["p_singular"].format(list=compress_positions(singular)),
                             "warning"))
    else:
        out.append(Paragraph(w["p_regular"]))
    return out


def reactions_section3(dyn: SpatialDynamics, model: Model, position: int,
                       display: Display, shown: Shown, lang: str, w: dict[str, str]
                       ) -> Section | None:
    """The section 'Reactions in the kinematic pairs' (None without ``joints:``)."""
    from mechloop.views.spatial_reactions import plot_spatial_hodograph, plot_spatial_reactions

    reactions = dyn.reactions
    if reactions is None:
        return None
    blocks: list = [solved_paragraph(dyn, reactions, w),
                    pairs_table3(reactions, model, shown, w),
                    *state_paragraphs(dyn, reactions, shown, w)]
    moments = any(_has_moment(r) for r in reactions.joints.values())
    blocks.append(FigureItem(w["f_reactions3m" if moments else "f_reactions3"],
                             lambda: translate(plot_spatial_reactions(dyn, display=display),
                                               lang)))
    rows = table_positions(dyn.kinematics.broken.size, position)
    for name, reaction in reactions.joints.items():
        blocks.append(Section(w["s_joint3"].format(name=name), [
            reaction_table(name, reaction, rows, shown, w),
            FigureItem(w["f_hodograph3"].format(name=name, position=position),
                       lambda name=name: translate(plot_spatial_hodograph(
                           dyn, name, position=position, display=display), lang))]))
    return Section(w["s_reactions"], blocks)


def agreement_lines(dyn: SpatialDynamics, shown: Shown, w: dict[str, str]
                    ) -> list[Paragraph]:
    """Per argument: how closely the balancing load by the reactions' equations equals
    the one by virtual power (the largest difference over the positions where both are
    known, and its share of the largest load)."""
    if dyn.reactions is None:
        return []
    # a rounding difference to two digits (five would print its noise)
    rough = Shown(TableDisplay(shown.td.units if shown.td is not None else {},
                               digits=AGREEMENT_DIGITS), shown.lang)
    out = []
    for k, vp in dyn.balancing.items():
        stem, unit = dyn.balancing_name(k)
        ne = np.asarray(dyn.reactions.balancing[k], dtype=float)
        both = np.isfinite(ne) & np.isfinite(vp)
        if not both.any():
            continue
        diff = float(np.abs(ne[both] - vp[both]).max())
        largest = float(np.abs(vp[both]).max())
        share = diff / largest if largest > 0 else 0.0
        out.append(Paragraph(w["bal_agree"].format(
            name=stem, diff=rough.text(diff, unit), share=rough.number(share),
            peak=shown.text(largest, unit))))
    return out


def reaction_lines(dyn: SpatialDynamics | None, shown: Shown, w: dict[str, str]
                   ) -> list[Paragraph]:
    """The conclusion's peak reaction force (joint, value, position) over every joint,
    and the peak reaction moment of the joints that have one."""
    if dyn is None or dyn.reactions is None:
        return []
    out = []
    for part, unit, key in (("force", "N", "peak_reaction"),
                            ("moment", "N*m", "peak_reaction_moment")):
        peaks = {name: peak(np.linalg.norm(getattr(r, part), axis=0))
                 for name, r in dyn.reactions.joints.items()
                 if part == "force" or _has_moment(r)}
        peaks = {n: p for n, p in peaks.items() if p is not None}
        if peaks:
            joint = max(peaks, key=lambda n: peaks[n][1])
            position, value = peaks[joint]
            out.append(Paragraph(w[key].format(name=joint, value=shown.text(value, unit),
                                               position=position)))
    return out
