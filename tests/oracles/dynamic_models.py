"""Dynamic models for the tests, as plain data (SI numbers, angles in degrees).

* :func:`example` — a bundled example file, with changes;
* :func:`four_bar` / :func:`slider_crank` — a crank-rocker four-bar and an offset
  slider-crank with bodies, loads and gravity;
* :func:`quick_return` — a crank and slotted lever (a prismatic pair between two moving
  bodies), and :func:`landing_gear` — examples/hydraulic_rocker.yaml with bodies (a length
  drive between the barrel and the rod of a cylinder);
* hypothesis strategies :func:`four_bars` and :func:`slider_cranks` that draw them with
  random dimensions, masses, inertias, centres (``{vector, share, across}`` or
  ``{vector, along, across}``), a force at a random point, a moment, gravity on or off.

Builders return the ``dict`` given to :meth:`mechloop.Model.from_dict`, so that an oracle
can read the same data the solver did.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path
from typing import Any

import yaml
from hypothesis import assume
from hypothesis import strategies as st

import mechloop
from mechloop.dynamics.analysis import DynamicResults, solve_dynamics

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def example(name: str, **changes: Any) -> dict:
    """The data of ``examples/<name>``, with top-level keys replaced (``None`` drops one)."""
    data = yaml.safe_load((EXAMPLES / name).read_text())
    for key, value in changes.items():
        if value is None:
            data.pop(key, None)
        else:
            data[key] = copy.deepcopy(value)
    return data


def crank_turn(n: int, theta0: float = 0.0) -> dict:
    """Argument 1 over positions 0..n: one turn at constant speed from ``theta0`` deg."""
    return {1: {"table": {0: theta0, n: theta0 + 360.0}}}


def dynamics(data: dict) -> DynamicResults:
    return solve_dynamics(mechloop.Model.from_dict(data))


def four_bar(a: float, b: float, c: float, g: float, *, ground: float = 0.0, variant: int = 1,
             n: int = 72, rpm: float = 300.0, theta0: float = 0.0, **dynamic: Any) -> dict:
    """Crank O–A (a, argument 1), coupler A–B (b), rocker B–D (c), frame D–O (g at
    ``ground`` degrees from O); bodies crank 1 = [1], coupler 2 = [2], rocker 3 = [3]
    unless ``dynamic`` says otherwise; joints inferred."""
    data = {
        "positions": n,
        "time": {"rpm": rpm},
        "arguments": crank_turn(n, theta0),
        "vectors": {1: {"r": a, "a": {"argument": 1}},
                    2: {"r": b, "a": "function"},
                    3: {"r": c, "a": "function"},
                    4: {"r": g, "a": ground + 180.0}},
        "contours": [{"vectors": [1, 2, 3, 4], "variant": variant}],
        "bodies": {1: {"vectors": [1]}, 2: {"vectors": [2]}, 3: {"vectors": [3]}},
    }
    data.update(copy.deepcopy(dynamic))
    return data


def slider_crank(a: float, b: float, e: float, *, guide: float = 0.0, n: int = 72,
                 rpm: float = 300.0, theta0: float = 0.0, **dynamic: Any) -> dict:
    """Crank O–A (a), rod A–B (b), slider B on a line at ``guide`` degrees offset by ``e``
    from O (vector 3 runs from B along the guide back to the foot of the offset, vector 4
    is the offset); bodies crank 1 = [1], rod 2 = [2], slider 3 = [3]; joints inferred."""
    data = {
        "positions": n,
        "time": {"rpm": rpm},
        "arguments": crank_turn(n, theta0),
        "vectors": {1: {"r": a, "a": {"argument": 1}},
                    2: {"r": b, "a": "function"},
                    3: {"r": "function", "a": guide + 180.0},
                    4: {"r": e, "a": guide + 90.0}},
        "contours": [{"vectors": [1, 2, 3, 4], "variant": 1}],
        "bodies": {1: {"vectors": [1]}, 2: {"vectors": [2]}, 3: {"vectors": [3]}},
    }
    data.update(copy.deepcopy(dynamic))
    return data


# ------------------------------------------------------------------------ strategies


@st.composite
def grashof_crank_rocker(draw, min_transmission: float = 0.0
                         ) -> tuple[float, float, float, float]:
    """(a, b, c, g) of a four-bar whose crank a turns fully: a Grashof crank-rocker (the
    crank the shortest link, s + l < p + q by a margin), so the transmission never
    reaches a toggle.

    With ``min_transmission`` (degrees) the transmission angle μ between coupler and rocker
    stays within [μ_min, 180° − μ_min] over the turn: as the crank turns, |A − D| runs over
    [g − a, g + a], and cos μ = (b² + c² − |A − D|²)/(2bc), so g ± a must stay within
    sqrt(b² + c² ∓ 2bc·cos μ_min).
    """
    if min_transmission <= 0:
        b, c, g = (draw(st.floats(0.2, 1.5)) for _ in range(3))
        longest = max(b, c, g)
        room = min(b + c + g - 2 * longest, min(b, c, g)) - 0.05 * longest
        assume(room > 0.08)
        return draw(st.floats(0.05, room)), b, c, g
    b, c = draw(st.floats(0.2, 1.5)), draw(st.floats(0.2, 1.5))
    k = math.cos(math.radians(min_transmission))
    lo, hi = math.sqrt(b * b + c * c - 2 * b * c * k), math.sqrt(b * b + c * c + 2 * b * c * k)
    g = lo + (hi - lo) * draw(st.floats(0.2, 0.8))
    a = min(g - lo, hi - g) * draw(st.floats(0.2, 0.95))
    return a, b, c, g


@st.composite
def point_on(draw, vector: int, length: float, *, sliding: bool = False) -> dict:
    """A point fixed in the body of ``vector``: ``{vector, share, across}`` or
    ``{vector, along, across}`` (only the latter on a vector of varying length)."""
    across = draw(st.floats(-0.5, 0.5)) * length
    if not sliding and draw(st.booleans()):
        return {"vector": vector, "share": draw(st.floats(-0.5, 1.5)), "across": across}
    return {"vector": vector, "along": draw(st.floats(-0.5, 1.5)) * length, "across": across}


@st.composite
def loads(draw, lengths: dict[int, float], sliding: frozenset[int] = frozenset()) -> dict:
    """Masses, inertias and centres of bodies 1..3 (one vector each, of length
    ``lengths[k]``), a force at a random point of a random body, a moment on a random
    body, gravity on or off."""
    bodies = {}
    for k, length in lengths.items():
        mass = draw(st.floats(0.1, 5.0))
        inertia = draw(st.one_of(st.floats(0.0, 0.2), st.just("rod"))) if k not in sliding \
            else draw(st.floats(0.0, 0.2))
        bodies[k] = {"vectors": [k], "mass": mass, "inertia": inertia,
                     "center": draw(point_on(k, length, sliding=k in sliding))}
    body = draw(st.sampled_from(sorted(lengths)))
    force = {"body": body, "at": draw(point_on(body, lengths[body], sliding=body in sliding)),
             "value": draw(st.floats(-1000.0, 1000.0)), "angle": draw(st.floats(-180.0, 180.0))}
    if draw(st.booleans()):
        force["along"] = body
    moment = {"body": draw(st.sampled_from(sorted(lengths))),
              "value": draw(st.floats(-100.0, 100.0))}
    out = {"bodies": bodies, "forces": [force], "moments": [moment]}
    if draw(st.booleans()):
        out["gravity"] = {"g": 9.81, "angle": draw(st.sampled_from([-90.0, 180.0, 30.0]))}
    return out


@st.composite
def four_bars(draw, n: int = 72, min_transmission: float = 0.0) -> dict:
    a, b, c, g = draw(grashof_crank_rocker(min_transmission))
    return four_bar(a, b, c, g, ground=draw(st.floats(-180.0, 180.0)),
                    variant=draw(st.sampled_from([1, 2])), n=n,
                    rpm=draw(st.floats(30.0, 600.0)), theta0=draw(st.floats(-180.0, 180.0)),
                    **draw(loads({1: a, 2: b, 3: c})))


@st.composite
def slider_cranks(draw, n: int = 72) -> dict:
    a = draw(st.floats(0.02, 0.5))
    e = draw(st.floats(-0.5, 0.5)) * a
    b = (a + abs(e)) * draw(st.floats(1.3, 5.0))
    return slider_crank(a, b, e, guide=draw(st.floats(-180.0, 180.0)), n=n,
                        rpm=draw(st.floats(30.0, 600.0)),
                        theta0=draw(st.floats(-180.0, 180.0)),
                        **draw(loads({1: a, 2: b, 3: b}, frozenset({3}))))


def quick_return(n: int = 72, *, friction: dict | None = None, block: int = 2,
                 lever: int = 3) -> dict:
    """Crank and slotted lever (the quick-return motion of a shaper): crank O–A (0.1 m,
    argument 1) carries a block at A that slides along a lever pivoted at C, 0.25 m above
    O.  Vector 2 runs A → C with unknown length and angle (Pl1): the block holds its tail,
    the lever (``ends: head``) its head, so the pair between them is prismatic along a
    turning guide.  Bodies: crank 1, the block and the lever numbered ``block`` and
    ``lever`` (2 and 3 either way); a force on the lever's pivot end, a moment on the lever,
    gravity."""
    data = {
        "positions": n, "time": {"rpm": 120.0}, "arguments": crank_turn(n, 10.0),
        "vectors": {1: {"r": 0.1, "a": {"argument": 1}},
                    2: {"r": "function", "a": "function"},
                    3: {"r": 0.25, "a": 90.0}},
        "contours": [{"vectors": [1, 2, 3]}],
        "bodies": {1: {"name": "crank", "vectors": [1], "mass": 1.0, "inertia": 0.002,
                       "center": {"vector": 1, "share": 0.5}},
                   block: {"name": "block", "vectors": [2], "mass": 0.5, "inertia": 0.0005,
                           "center": {"tail": 2}},
                   lever: {"name": "lever", "vectors": [2], "ends": {2: "head"}, "mass": 3.0,
                           "inertia": 0.08, "center": {"head": 2}}},
        "forces": [{"body": lever, "at": {"head": 2}, "value": 50.0, "angle": 0.0}],
        "moments": [{"body": lever, "value": -20.0}],
        "gravity": {"g": 9.81},
    }
    if friction is not None:
        data["friction"] = friction
    return data


def landing_gear(n: int = 400) -> dict:
    """examples/hydraulic_rocker.yaml with bodies: the leg (lug + leg, two lumped masses),
    the cylinder barrel pivoted on the airframe (holds the head of vector 2) and the piston
    rod pinned to the lug (holds its tail); a drag force on the wheel axle and a force
    along the leg; gravity."""
    return example(
        "hydraulic_rocker.yaml",
        positions=n,
        time={"table": {0: 0.0, n: 4.0}},
        arguments={1: {"law": "poly345", "start": [0, 0.60], "end": [n, 0.85]}},
        bodies={
            1: {"name": "leg", "vectors": [1, 4], "mass": 40.0, "inertia": 6.0,
                "center": {"vector": 4, "share": 0.5, "across": 0.05},
                "parts": [{"mass": 15.0, "inertia": 0.2, "center": {"head": 4}}]},
            2: {"name": "barrel", "vectors": [2], "ends": {2: "head"}, "mass": 6.0,
                "inertia": 0.1, "center": {"head": 2}},
            3: {"name": "piston rod", "vectors": [2], "mass": 3.0, "inertia": 0.05,
                "center": {"vector": 2, "along": 0.15}},
        },
        forces=[{"body": 1, "at": {"head": 4}, "value": 500.0, "angle": 180.0},
                {"body": 1, "at": {"vector": 4, "share": 0.7}, "value": 300.0, "angle": 90.0,
                 "along": 4}],
        gravity={"g": 9.81},
    )


def four_bar_data(coupler: float, positions: int = 72, *, crank: float = 0.1,
                  frame: float = 0.3, rocker: float = 0.25) -> dict[str, Any]:
    """A crank-rocker four-bar model (m, deg) driven at its crank over one turn in
    ``positions`` steps at 60 rpm, three rod-like bodies; with ``coupler + rocker <
    crank + frame`` the crank cannot pass the angle where its pin is ``coupler + rocker``
    from the rocker's pivot (the chain breaks there)."""
    return {"units": {"length": "m", "angle": "deg"}, "positions": positions,
            "time": {"rpm": 60}, "arguments": {1: {"table": {0: 0, positions: 360}}},
            "vectors": {1: {"r": crank, "a": {"argument": 1}},
                        2: {"r": coupler, "a": "function"},
                        3: {"r": rocker, "a": "function"}, 4: {"r": frame, "a": 180}},
            "contours": [{"vectors": [1, 2, 3, 4], "variant": 1}],
            "bodies": {1: {"vectors": [1], "mass": 1, "inertia": 0.001,
                           "center": {"vector": 1, "share": 0.5}},
                       2: {"vectors": [2], "mass": 0.5, "inertia": "rod",
                           "center": {"vector": 2, "share": 0.5}},
                       3: {"vectors": [3], "mass": 0.8, "inertia": "rod",
                           "center": {"vector": 3, "share": 0.5}}}}
