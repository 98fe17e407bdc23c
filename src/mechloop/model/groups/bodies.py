"""The dynamic part of a built model: bodies (with their masses and centres), joints,
forces and moments on links, placed on the vectors of each link.
"""

from __future__ import annotations

import cmath
import math
from typing import Any

from mechloop.errors import Problem
from mechloop.model.dynamic import (
    HeadPoint,
    TailPoint,
    VectorPoint,
)
from mechloop.model.groups.core import GROUND, _Link
from mechloop.model.groups.names import NameSteps
from mechloop.model.groups.spec import Share
from mechloop.model.units import UnitProblem, to_si, unit_factor


class BodySteps(NameSteps):
    """Writes the model data: vectors, contours, bodies, joints, loads."""

    def model_data(self) -> dict[str, Any]:
        mech = self.mech
        vectors = {}
        for number, vec in self.vectors.items():
            vectors[number] = {"r": self.role(vec.r, "r", vec.reversed),
                               "a": self.role(vec.a, "a", vec.reversed), "name": vec.name}
        data: dict[str, Any] = {
            "name": mech.name, "description": mech.description, "units": mech.units,
            "positions": mech.positions, "time": mech.time, "arguments": mech.arguments,
            "vectors": vectors, "contours": self.contours, "bodies": self.bodies(),
            "joints": self.joints(), "friction": mech.friction,
        }
        for key in ("gravity", "machine", "project"):
            if getattr(mech, key) is not None:
                data[key] = getattr(mech, key)
        data["forces"] = self.forces()
        data["moments"] = [{"body": self.links[m.link].body, "value": m.value,
                            **({"name": m.name} if m.name else {})}
                           for i, m in enumerate(mech.moments)
                           if self.link_of(m.link, ("moments", i, "link"))]
        return data

    def bodies(self) -> dict[int, dict[str, Any]]:
        out: dict[int, dict[str, Any]] = {}
        ground_slides: list[int] = []
        for link in self.links.values():
            if link.name == GROUND:
                continue
            order = sorted(set(link.segments), key=lambda s: (s != link.ref, s))
            numbers = [self.segs[s].vector for s in order]
            body: dict[str, Any] = {"name": link.name, "vectors": numbers}
            ends = {}
            for s in order:
                seg = self.segs[s]
                if seg.held:
                    end = next(e for e, owner in seg.held.items() if owner == link.name)
                    ends[seg.vector] = "head" if (end == "head") != seg.reversed else "tail"
                    if seg.held.get("tail" if end == "head" else "head") == GROUND \
                            and seg.r[0] == "arg":
                        ground_slides.append(s)
            if ends:
                body["ends"] = ends
            body.update(self.mass(link))
            out[link.body] = body
        if ground_slides:  # a driven slide: its other end is held by the ground
            segs = [self.segs[s] for s in ground_slides]
            out[0] = {"name": GROUND, "vectors": [s.vector for s in segs],
                      "ends": {s.vector: "tail" if (s.held["tail"] == GROUND) != s.reversed
                               else "head" for s in segs}}
        return dict(sorted(out.items()))

    def joints(self) -> dict[str, dict[str, Any]]:
        out: dict[str, dict[str, Any]] = {}

        def name_for(base: str) -> str:
            if base not in out:
                return base
            n = 2
            while f"{base}{n}" in out:
                n += 1
            return f"{base}{n}"

        pins = [(n, a, b, s, e, None) for n, a, b, s, e in self.pins]
        for n, first, second, seg, end, along in pins + [
                (n, a, b, s, e, al) for n, a, b, al, s, e in self.slides]:
            entry: dict[str, Any] = {
                "type": "revolute" if along is None else "prismatic",
                "bodies": [self.links[first].body, self.links[second].body],
                "at": self.end_of(seg, end)}
            if along is not None:
                entry["along"] = self.segs[along].vector
            out[name_for(n)] = entry
        return out

    def place_on(self, link: _Link, spec: Any, path: tuple
                 ) -> tuple[TailPoint | HeadPoint | VectorPoint, int, float] | None:
        """A place on ``link`` as a point on one of its vectors, with a vector of the body
        and that vector's angle from the link's line (for directions)."""
        if isinstance(spec, Share):
            if link.second is None:
                self.problems.append(Problem(path, f"link {link.name!r} has no second point, "
                                             "so no line to take a share of",
                                             "give a point name or {from: X, distance: d, "
                                             "angle: φ}"))
                return None
            a, b = link.local[link.first], link.local[link.second]
            local = a + spec.share * (b - a)
            for s in link.segments:
                seg = self.segs[s]
                if seg.r[0] == "const" and {seg.tail, seg.head} == {link.first, link.second}:
                    share = spec.share if seg.tail == link.first else 1.0 - spec.share
                    if seg.reversed:
                        share = 1.0 - share
                    return VectorPoint(vector=seg.vector, share=share), *self.direction(link)
        elif isinstance(spec, str):
            name = spec.split(".")[-1].strip()
            if name not in link.local:
                self.problems.append(Problem(path, f"{name!r} is not a point of link "
                                             f"{link.name!r}", f"use one of "
                                             f"{', '.join(link.local)}"))
                return None
            for s in link.segments:
                seg = self.segs[s]
                for end in ("tail", "head"):
                    point = seg.tail if end == "tail" else seg.head
                    fixed = seg.r[0] == "const" or seg.held.get(end) == link.name
                    if point == name and fixed:
                        return self.end_of(s, end), *self.direction(link)
            local = link.local[name]
        else:
            origin = (spec.from_ or link.first or "").split(".")[-1].strip()
            if origin not in link.local:
                self.problems.append(Problem((*path, "from"), f"{origin!r} is not a point of "
                                             f"link {link.name!r}", f"use one of "
                                             f"{', '.join(link.local)}"))
                return None
            d = self.num(spec.distance, "length", (*path, "distance"))
            phi = self.num(spec.angle, "angle", (*path, "angle"))
            local = link.local[origin] + d * cmath.exp(1j * phi * math.pi / self.half)
        for s in link.segments:
            seg = self.segs[s]
            tail_end = "head" if seg.reversed else "tail"  # the seg end at the vector's tail
            tail_point = seg.head if seg.reversed else seg.tail
            fixed = seg.r[0] == "const" or seg.held.get(tail_end) == link.name
            if not fixed or tail_point not in link.local:
                continue
            delta = self.line_delta(link, s) * math.pi / self.half
            w = (local - link.local[tail_point]) * cmath.exp(-1j * delta)
            return (VectorPoint(vector=seg.vector, along=w.real, across=w.imag),
                    *self.direction(link))
        self.problems.append(Problem(path, f"link {link.name!r} has no vector with a fixed "
                                     "tail to place this point from",
                                     f"define a point there (points: {{S: {{link: "
                                     f"{link.name}, from: ..., distance: ..., angle: ...}}}}) "
                                     "and name it"))
        return None

    def direction(self, link: _Link) -> tuple[int, float]:
        assert link.ref is not None
        return self.segs[link.ref].vector, self.line_delta(link, link.ref)

    def line_delta(self, link: _Link, s: int) -> float:
        """Angle of segment ``s``'s written vector from the line of ``link`` (model
        units)."""
        seg = self.segs[s]
        return self.seg_delta(link, s) + (self.half if seg.reversed else 0.0)

    def seg_delta(self, link: _Link, s: int) -> float:
        """Angle of segment ``s`` (as defined, tail to head) from the line of ``link``."""
        if s == link.ref:
            return link.ref_delta
        template = self.segs[s].a
        assert template[0] == "link", "a vector of a moving link follows the link's angle"
        return template[3] + self.seg_delta(link, template[1])

    def mass(self, link: _Link) -> dict[str, Any]:
        spec = self.mech.masses.get(link.name)
        if spec is None:
            return {}
        path = ("masses", link.name)
        out: dict[str, Any] = {"mass": spec.mass}
        if spec.center is None:
            self.problems.append(Problem(path, f"link {link.name!r} has a mass but no centre "
                                         "of mass", "add center: a point name, {share: "
                                         "0.5} or {from: A, distance: d, angle: φ}"))
            return out
        placed = self.place_on(link, spec.center, (*path, "center"))
        if placed is None:
            return out
        out["center"] = placed[0]
        if spec.inertia == "rod":
            if link.second is None:
                self.problems.append(Problem((*path, "inertia"), f"'rod' needs the length of "
                                             f"the link, and {link.name!r} has no second "
                                             "point", "give the moment of inertia as a "
                                             "number"))
                return out
            if isinstance(placed[0], VectorPoint) and self._on_line(link, placed[0].vector):
                out["inertia"] = "rod"  # from the line vector's length: follows synthesis
                return out
            length = abs(link.local[link.second] - link.local[link.first])
            units = self.units
            try:
                m = to_si(spec.mass, "mass", units.mass)
                inertia = m * (length * unit_factor(units.length, "length")) ** 2 / 12.0
                out["inertia"] = inertia / unit_factor(units.inertia, "inertia")
            except UnitProblem as exc:
                self.problems.append(Problem((*path, "mass"), exc.message, exc.hint))
        else:
            out["inertia"] = spec.inertia
        return out

    def _on_line(self, link: _Link, vector: int) -> bool:
        """Whether ``vector`` is the link's line from its first to its second point, of
        constant length."""
        return any(self.segs[s].vector == vector and self.segs[s].r[0] == "const"
                   and {self.segs[s].tail, self.segs[s].head} == {link.first, link.second}
                   for s in link.segments)

    def forces(self) -> list[dict[str, Any]]:
        out = []
        for i, f in enumerate(self.mech.forces):
            path = ("forces", i)
            link = self.link_of(f.link, (*path, "link"))
            if link is None:
                continue
            placed = self.place_on(link, f.at, (*path, "at"))
            if placed is None:
                continue
            at, vector, delta = placed
            entry: dict[str, Any] = {"body": link.body, "at": at, "value": f.value,
                                     "angle": f.angle}
            if f.follow:
                entry["along"] = vector
                entry["angle"] = self.num(f.angle, "angle", (*path, "angle")) - delta
            if f.name:
                entry["name"] = f.name
            out.append(entry)
        return out
