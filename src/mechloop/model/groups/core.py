"""The core of the group builder (:class:`BuilderCore`): its state — segments, links,
points, pins and slides — and the steps every group kind uses: reading numbers in model
units, resolving point references, writing segments as vectors and contours (a segment
written once, linked copies afterwards), guides and points fixed in links.

Role templates: ``("const", value, dim)``, ``("function",)``, ``("arg", k, offset, dim)``,
``("link", segment, letter, delta, dim)``; ``dim`` names the dimension a constant carries.
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass, field
from difflib import get_close_matches
from typing import Any

from mechloop.errors import Problem, format_path
from mechloop.model.dynamic import (
    HeadPoint,
    TailPoint,
)
from mechloop.model.groups.spec import GROUND, GroupMechanism, Variant
from mechloop.model.signals import Scalar
from mechloop.model.units import Kind, UnitProblem, to_si, unit_factor

# role templates: ("const", value, dim) | ("function",) | ("arg", k, offset, dim)
#                 | ("link", segment, letter, delta, dim)
Template = tuple


_GROUND_XY = re.compile(r"^ground\.([^.]+)\.([xy])$")


@dataclass(frozen=True)
class _At:
    """A contour start at the coordinates of a ground point."""

    ground: str


@dataclass
class _Seg:
    """A vector of the mechanism before it is written: from point ``tail`` to ``head``."""

    id: int
    name: str
    tail: str
    head: str
    r: Template
    a: Template
    link: str  # the link it is fixed in (ground for frames and ground offsets)
    held: dict[str, str] = field(default_factory=dict)  # end -> link, for sliding vectors
    vector: int | None = None
    reversed: bool = False


@dataclass
class _Link:
    name: str
    body: int
    ref: int | None  # segment whose angle is the line's plus ref_delta
    ref_delta: float
    local: dict[str, complex]  # points fixed in the link, in the line frame
    first: str | None
    second: str | None
    segments: list[int] = field(default_factory=list)


@dataclass
class _Point:
    name: str
    owners: tuple[str, ...]  # the link(s) that introduced it
    links: list[str]
    ground: str  # the ground point its chain starts at
    path: tuple[tuple[int, int], ...]  # (segment, +1 forward / -1 backward)
    broken: bool = False


@dataclass
class _Vec:
    name: str
    r: Template
    a: Template
    reversed: bool


class BuilderCore:
    """The builder's state and its elementary steps: numbers, point names, segments (the
    vectors before they are written), contours, guides and points on links."""

    def __init__(self, mech: GroupMechanism):
        self.mech = mech
        self.units = mech.units
        self.problems: list[Problem] = []
        self.segs: list[_Seg] = []
        self.vectors: dict[int, _Vec] = {}
        self.contours: list[dict[str, Any]] = []
        self.links: dict[str, _Link] = {}
        self.points: dict[str, _Point] = {}
        self.pins: list[tuple[str, str, str, int, str]] = []  # name, link1, link2, seg, end
        self.slides: list[tuple[str, str, str, int, int, str]] = []  # + along segment
        self.dims: dict[str, float] = {}
        self.input_segs: set[int] = set()
        self.frames: dict[str, int] = {}
        self.coords: dict[str, complex] = {}
        self.root = next(iter(mech.ground))
        self.half = 0.0
        self.link_names: dict[str, tuple] = {}
        self.declared: dict[str, tuple[str, tuple]] = {}  # set by NameSteps.declare
        self.pending = dict(mech.points)
        self.starts: dict[int, str] = {}  # contour number -> the ground point it starts at
        task = mech.synthesis
        self.moved = {name.split(".")[1] for name in (task.vary if task else ())
                      if _GROUND_XY.match(name)}  # ground points synthesis moves

    # -- numbers -----------------------------------------------------------------------

    def num(self, value: Scalar, kind: Kind, path: tuple, *, positive: bool = False,
            dim: str | None = None) -> float:
        """``value`` in the model's unit of ``kind``; records a problem and returns 0 when
        it cannot be read."""
        unit = getattr(self.units, kind)
        try:
            si = to_si(value, kind, unit)  # refuses unreadable, non-finite, absurd values
            out = _plain(value)
            if out is None:  # a quantity with its own unit: to SI, then to the model's
                out = si / unit_factor(unit, kind)
        except UnitProblem as exc:
            self.problems.append(Problem(path, exc.message, exc.hint))
            return 0.0
        if positive and not out > 0:
            self.problems.append(Problem(path, f"{format_path(path)} is {out:g}; a length "
                                         "here must be positive", "give a positive length"))
        if dim is not None:
            self.dims[dim] = out
        return out

    # -- segments and roles --------------------------------------------------------------

    def seg(self, name: str, tail: str, head: str, r: Template, a: Template, link: str,
            held: dict[str, str] | None = None) -> int:
        """A new segment; ``held`` names the links at the two ends of a sliding one."""
        self.segs.append(_Seg(len(self.segs), name, tail, head, r, a, link, held or {}))
        return len(self.segs) - 1

    def angle_on(self, link: str, angle: float, dim: str | None = None) -> Template:
        """Template of an angle ``angle`` from the line of ``link`` (from +X: ground)."""
        owner = self.links[link]
        if owner.ref is None:
            return ("const", angle, dim)
        return ("link", owner.ref, "a", angle - owner.ref_delta, dim)

    def new_point(self, name: str, owners: tuple[str, ...], ground: str,
                  path: tuple[tuple[int, int], ...], broken: bool = False) -> None:
        """A new named point, carried by ``owners``, reached by ``path`` from ``ground``."""
        self.points[name] = _Point(name, owners, list(owners), ground, path, broken)

    def new_link(self, name: str, ref: int | None, ref_delta: float,
                 local: dict[str, complex], first: str | None, second: str | None) -> _Link:
        """A new link (body number: the next one) with the points fixed in it."""
        link = _Link(name, len(self.links), ref, ref_delta, local, first, second)
        self.links[name] = link
        for point in local:
            if point in self.points and name not in self.points[point].links:
                self.points[point].links.append(name)
        return link

    def frame(self, name: str) -> int:
        """The frame segment from the root to ground point ``name``."""
        if name not in self.frames:
            d = self.coords[name] - self.coords[self.root]
            r = abs(d)
            a = math.degrees(cmath.phase(d)) * (self.half / 180.0) if r > 0 else 0.0
            self.dims[f"ground.{name}.distance"] = r
            self.dims[f"ground.{name}.direction"] = a
            self.frames[name] = self.seg(f"frame {self.root}{name}", self.root, name,
                                         ("const", r, f"ground.{name}.distance"),
                                         ("const", a, f"ground.{name}.direction"), GROUND)
        return self.frames[name]

    # -- contours ------------------------------------------------------------------------

    def place(self, seg_id: int, direction: int, out: list[int]) -> None:
        """Put segment ``seg_id`` (traversed forward or backward) in a contour: the vector
        itself the first time, a linked copy afterwards."""
        seg = self.segs[seg_id]
        number = len(self.vectors) + 1
        if seg.vector is None:
            seg.vector, seg.reversed = number, direction < 0
            name = seg.name
            if seg.reversed:
                ends = f"{seg.tail}{seg.head}"
                name = (f"{name[:-len(ends)]}{seg.head}{seg.tail}" if name.endswith(ends)
                        else f"{name} (reversed)")
            self.vectors[number] = _Vec(name, seg.r, seg.a, seg.reversed)
        else:
            delta = 0.0 if direction > 0 else self.half
            suffix = "copy" if direction > 0 else "reversed copy"
            self.vectors[number] = _Vec(f"{seg.name} ({suffix})",
                                        ("link", seg_id, "r", 0.0, None),
                                        ("link", seg_id, "a", delta, None), False)
        out.append(number)

    def end_of(self, seg_id: int, end: str) -> TailPoint | HeadPoint:
        """The written vector's end at the segment's ``end``."""
        seg = self.segs[seg_id]
        assert seg.vector is not None
        tail = (end == "tail") != seg.reversed
        return TailPoint(tail=seg.vector) if tail else HeadPoint(head=seg.vector)

    def loop(self, side1: tuple[str, tuple], own: list[tuple[int, int]],
             side2: tuple[str, tuple], *, name: str, variant: Variant, module: str) -> None:
        """One contour: from a ground point along ``side1`` (a chain to the first
        attachment), the group's own segments, back along ``side2`` and through the
        ground.

        When only ``side2`` meets the input's vector before it is written, the loop is
        written the other way round, so that the input's vector keeps its direction (the
        argument is its angle): a Pl1, Pl2 or Pl3 loop has the same solution either way, a
        Pl4 loop swaps its variants (not done for ``auto``, which starts from variant 1).
        """
        def meets_input(chain: tuple) -> bool:
            return any(s in self.input_segs and self.segs[s].vector is None for s, _ in chain)

        if meets_input(side2[1]) and not meets_input(side1[1]) and not (
                module == "Pl4" and variant == "auto"):
            side1, side2 = side2, side1
            own = [(s, -d) for s, d in reversed(own)]
            if module == "Pl4":
                variant = 2 if variant == 1 else 1
        g1, s1 = side1
        g2, s2 = side2
        common = 0
        if g1 == g2:
            while (common < min(len(s1), len(s2)) and s1[common] == s2[common]
                   and self.segs[s1[common][0]].vector is not None):
                common += 1
        elements = list(s1[common:]) + own + [(s, -d) for s, d in reversed(s2[common:])]
        if g1 != g2:
            if g2 != self.root:
                elements.append((self.frame(g2), -1))
            if g1 != self.root:
                elements.append((self.frame(g1), +1))
        start: Any
        if common:
            seg_id, direction = s1[common - 1]
            start = self.end_of(seg_id, "head" if direction > 0 else "tail")
        else:
            start = self.start_at(g1)
        self.contour(elements, start=start, name=name, variant=variant)

    def start_at(self, ground: str) -> _At:
        """A contour start at the coordinates of ground point ``ground``."""
        return _At(ground)

    def contour(self, elements: list[tuple[int, int]], *, start: Any, name: str,
                variant: Variant = 1) -> None:
        numbers: list[int] = []
        for seg_id, direction in elements:
            self.place(seg_id, direction, numbers)
        if isinstance(start, _At):  # coordinates (kept even at 0, 0 if synthesis moves them)
            self.starts[len(self.contours) + 1] = start.ground
            z = self.coords[start.ground]
            start = "origin" if z == 0 and start.ground not in self.moved else (z.real,
                                                                                 z.imag)
        entry: dict[str, Any] = {"vectors": numbers, "name": name}
        if variant != 1:
            entry["variant"] = variant
        if start != "origin":
            entry["start"] = start
        self.contours.append(entry)

    def closing(self, seg_id: int, start: Any, name: str) -> None:
        """A Pl1 contour that holds segment ``seg_id`` alone: the segment and a vector of
        unknown length and angle back to its tail."""
        seg = self.segs[seg_id]
        closer = self.seg(f"closing {seg.head}{seg.tail}", seg.head, seg.tail, ("function",),
                          ("function",), GROUND)
        self.contour([(seg_id, +1), (closer, +1)], start=start, name=name)

    def handle(self, point: str) -> Any:
        """A contour start at ``point``: a written vector end there, or ground coords."""
        if point in self.coords:
            return self.start_at(point)
        for seg in self.segs:
            if seg.vector is not None and point in (seg.tail, seg.head):
                return self.end_of(seg.id, "tail" if seg.tail == point else "head")
        raise AssertionError(f"point {point} is not placed")  # every placed point has one

    # -- output ----------------------------------------------------------------------------

    def role(self, template: Template, letter: str, reversed_: bool) -> Any:
        turn = self.half if reversed_ and letter == "a" else 0.0
        kind = template[0]
        if kind == "const":
            return _tidy(template[1] + turn, self.half) if letter == "a" else template[1]
        if kind == "function":
            return "function"
        if kind == "arg":
            offset = _tidy(template[2] + turn, self.half) if letter == "a" else template[2]
            return {"argument": template[1], "offset": offset}
        target = self.segs[template[1]]
        back = self.half if target.reversed and letter == "a" else 0.0
        delta = template[3] + turn - back
        if letter == "a":
            delta = _tidy(delta, self.half)
        return {"link": f"{letter}{target.vector}", "delta": delta}


def _plain(value: Scalar) -> float | None:
    """A number in model units as a float (exactly as written); None for a quantity."""
    if not isinstance(value, str):
        return float(value)
    try:
        return float(value.strip())
    except ValueError:
        return None


def _tidy(angle: float, half: float) -> float:
    """An angle folded into (−half, half] (half a turn in model units) by whole turns
    (exactly, in one step: :func:`math.remainder`)."""
    folded = math.remainder(angle, 2 * half)
    return half if folded == -half else folded


def _choose(name: str, options: list[str], what: str | None = None) -> str:
    close = get_close_matches(name, options, n=1)
    listed = ", ".join(options) if options else "none yet"
    hint = f"use one of: {listed}" + (f" ({what})" if what else "")
    return f"did you mean {close[0]!r}? " + hint if close else hint
