"""Places fixed in links: guides (the line a slide runs along, with its offset) and the
named points of ``points:`` measured on the link that carries them.
"""

from __future__ import annotations

import cmath
import math

from mechloop.errors import Problem
from mechloop.model.groups.core import GROUND, _Point
from mechloop.model.groups.names import NameSteps
from mechloop.model.groups.spec import Guide


class PlaceSteps(NameSteps):
    """Guides and points fixed in links."""

    def guide(self, spec: Guide, path: tuple, dim: str
              ) -> tuple[_Point, float, float | None] | None:
        """The point a guide runs through, its angle and offset (model units)."""
        through = self.resolve(spec.through, (*path, "through"))
        angle = self.num(spec.angle, "angle", (*path, "angle"), dim=f"{dim}.angle")
        offset = None if spec.offset is None else self.num(spec.offset, "length",
                                                           (*path, "offset"),
                                                           dim=f"{dim}.offset")
        return None if through is None else (through, angle, offset)

    def guide_chain(self, through: _Point, offset: float | None, slide: int, turn: float,
                    dim: str, name: str) -> tuple[tuple[int, int], ...]:
        """The chain to the guide's origin (the foot of the slide): the chain of
        ``through`` plus the offset segment, whose direction is the slide's turned by
        ``turn`` degrees."""
        if offset is None:
            return through.path
        link = through.links[0]
        off = self.seg(name, through.name, ".foot", ("const", offset, f"{dim}.offset"),
                       ("link", slide, "a", turn * self.half / 180.0, None), link)
        if link != GROUND:
            self.links[link].segments.append(off)
        return (*through.path, (off, +1))

    def add_points(self, link: str) -> None:
        """Register the points of ``points`` that are fixed in ``link`` (in file order)."""
        owner = self.links[link]
        for name, spec in list(self.pending.items()):
            if spec.link != link:
                continue
            del self.pending[name]
            path = ("points", name)
            distance = self.num(spec.distance, "length", (*path, "distance"), positive=True,
                                dim=f"points.{name}.distance")
            angle = self.num(spec.angle, "angle", (*path, "angle"),
                             dim=f"points.{name}.angle")
            origin_name = spec.from_ or owner.first
            if owner.ref is None:  # the link itself failed
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            later = (origin_name or "").split(".")[-1].strip()
            if later in self.pending and self.pending[later].link == link:
                self.problems.append(Problem((*path, "from"), f"point {name} is measured from "
                                             f"{later}, which is listed after it",
                                             f"list {later} before {name} under points:"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            if origin_name is None:
                self.problems.append(Problem((*path, "from"), f"link {link!r} has no first "
                                             "point to measure from", "give from: a point "
                                             "of the link"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            origin = self.resolve(f"{link}.{origin_name.split('.')[-1]}", (*path, "from"))
            if origin is None:
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            if origin.name not in owner.local:
                self.problems.append(Problem((*path, "from"), f"{origin.name} is not a fixed "
                                             f"point of link {link!r}",
                                             f"measure from one of {', '.join(owner.local)}"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            seg = self.seg(f"{link} point {name}", origin.name, name,
                           ("const", distance, f"points.{name}.distance"),
                           self.angle_on(link, angle, f"points.{name}.angle"), link)
            owner.local[name] = owner.local[origin.name] + distance * cmath.exp(
                1j * angle * math.pi / self.half)
            owner.segments.append(seg)
            self.new_point(name, (link,), origin.ground, (*origin.path, (seg, +1)))
