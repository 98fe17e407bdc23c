"""Named points and dimensions of a built model: where each point is, which parameters
carry each dimension, and the vector model's synthesis task written from a group file's.
"""

from __future__ import annotations

from typing import Any, Literal

from mechloop.errors import Problem
from mechloop.model.groups.core import _GROUND_XY, GROUND, BuilderCore, _choose
from mechloop.model.groups.located import Carrier, PointLocation
from mechloop.model.groups.spec import GroupSynthesisTask
from mechloop.model.synthesis import (
    Tie,
)


class DimensionSteps(BuilderCore):
    """Point locations, carriers and the synthesis task."""

    def locations(self) -> dict[str, PointLocation]:
        out = {}
        for name, point in self.points.items():
            if name not in self.declared or point.broken:
                continue
            signed = []
            for seg_id, direction in point.path:
                seg = self.segs[seg_id]
                assert seg.vector is not None
                signed.append(seg.vector if (direction > 0) != seg.reversed else -seg.vector)
            end = None
            for seg in sorted(self.segs, key=lambda s: s.vector or 1 << 30):
                if seg.vector is not None and name in (seg.tail, seg.head):
                    end = self.end_of(seg.id, "tail" if seg.tail == name else "head")
                    break
            z = self.coords[point.ground]
            out[name] = PointLocation(name, (z.real, z.imag), tuple(signed), end,
                                      tuple(point.links))
        return out

    def dimension_names(self) -> list[str]:
        """What synthesis may vary: every carried dimension (a ground point by its x and y
        rather than its polar form from the root)."""
        carried = [k for k in self.carriers() if not k.startswith(f"{GROUND}.")]
        return carried + [f"{GROUND}.{g}.{axis}" for g in self.mech.ground for axis in "xy"]

    def ties(self, name: str, varied: set[str], carried: dict[str, tuple[Carrier, ...]]
             ) -> tuple[float, list[Tie]]:
        """The value of dimension ``name`` (model units) and the constants it sets, when
        the dimensions ``varied`` are varied together.

        A ground point's coordinate sets the starts of the contours that start there and
        a component of every frame vector it ends (from the root: the point minus the
        root, negated when the written vector is reversed); the other point's part of that
        component is the shift unless it is varied too.
        """
        match = _GROUND_XY.match(name)
        if match is None:
            return self.dims[name], [Tie(set=c.parameter, shift=c.shift)
                                     for c in carried[name]]
        ground, axis = match.groups()
        pick = (lambda z: z.real) if axis == "x" else (lambda z: z.imag)
        ties = [Tie(set=f"start{k}.{axis}") for k, g in self.starts.items() if g == ground]
        for other, seg_id in self.frames.items():
            seg = self.segs[seg_id]
            sign = -1.0 if seg.reversed else 1.0
            if ground == other:
                factor, partner = sign, self.root
            elif ground == self.root:
                factor, partner = -sign, other
            else:
                continue
            shift = 0.0 if f"{GROUND}.{partner}.{axis}" in varied else \
                -factor * pick(self.coords[partner]) + 0.0
            ties.append(Tie(set=f"v{seg.vector}.{axis}", factor=factor, shift=shift))
        return pick(self.coords[ground]), ties

    def synthesis(self, task: GroupSynthesisTask) -> dict[str, Any]:
        """The vector model's synthesis task: each varied dimension with the constants it
        sets (``dimensions``), named points as vector ends."""
        base = ("synthesis",)
        if task.dimensions:
            self.problems.append(Problem((*base, "dimensions"), "a group file names its "
                                         "dimensions in vary:; mechloop writes "
                                         "dimensions: into the vector model",
                                         "remove dimensions:"))
        carried = self.carriers()
        names = self.dimension_names()
        dims: dict[str, Any] = {}
        for name in task.vary:
            if name not in names:
                self.problems.append(Problem((*base, "vary", name), f"no dimension named "
                                             f"{name!r}", _choose(name, names, "dimensions "
                                             "as the file spells them")))
                continue
            value, ties = self.ties(name, set(task.vary), carried)
            if not ties:
                self.problems.append(Problem((*base, "vary", name), f"{name} moves nothing: "
                                             "no contour passes that ground point",
                                             "vary a point that a group uses"))
                continue
            dims[name] = {"value": value, "sets": [t.model_dump() for t in ties]}
        data = task.model_dump(mode="json", by_alias=True, exclude_defaults=True,
                               exclude={"dimensions"})
        data["dimensions"] = dims
        locations = self.locations()

        def end(ref: str, path: tuple) -> Any:
            link, _, name = ref.strip().rpartition(".")
            where = locations.get(name.strip())
            if where is None:
                self.problems.append(Problem(path, f"no point named {name.strip()!r}",
                                             _choose(name.strip(), list(locations),
                                                     "named points")))
            elif link and link.strip() not in where.links:
                self.problems.append(Problem(path, f"point {where.name!r} is not on link "
                                             f"{link.strip()!r}", f"{where.name} is on "
                                             f"{', '.join(where.links)}"))
            elif where.end is None:
                self.problems.append(Problem(path, f"{where.name} is a ground point that no "
                                             "vector reaches", "trace a point of a link"))
            else:
                return where.end.model_dump()
            return {"head": 1}

        if task.path is not None:
            data["path"]["point"] = end(task.path.point, (*base, "path", "point"))
        if task.motion is not None:
            data["motion"]["point"] = end(task.motion.point, (*base, "motion", "point"))
        if task.workspace is not None:
            data["workspace"]["points"] = [
                end(ref, (*base, "workspace", "points", i))
                for i, ref in enumerate(task.workspace.points)]
        return data

    def carriers(self) -> dict[str, tuple[Carrier, ...]]:
        found: dict[str, list[Carrier]] = {}
        for seg in self.segs:
            if seg.vector is None:
                continue
            for letter in "ra":
                template = seg.r if letter == "r" else seg.a
                dim = template[-1] if template[0] in ("const", "arg", "link") else None
                if dim is None or dim not in self.dims:
                    continue
                role = self.role(template, letter, seg.reversed)
                part: Literal["value", "delta", "offset"]
                if isinstance(role, dict):
                    part = "offset" if "argument" in role else "delta"
                    value = role["offset" if "argument" in role else "delta"]
                else:
                    part, value = "value", role
                shift = round(value - self.dims[dim], 9) + 0.0
                found.setdefault(dim, []).append(Carrier(f"{letter}{seg.vector}", part, shift))
        return {k: tuple(v) for k, v in found.items()}
