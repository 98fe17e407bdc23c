"""The group builder: the input, each group in file order (dyads and triads), the loose
ends, and the checked vector model with its point locations and carriers.
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import ValidationError

from mechloop.errors import ModelError, Problem
from mechloop.model.check import check_model
from mechloop.model.groups.bodies import BodySteps
from mechloop.model.groups.core import GROUND, _choose, _Link
from mechloop.model.groups.dimensions import DimensionSteps
from mechloop.model.groups.dyads import DyadSteps
from mechloop.model.groups.inputs import InputSteps
from mechloop.model.groups.located import BuiltModel
from mechloop.model.groups.spec import KIND, Triad, Variant
from mechloop.model.groups.triads import TriadSteps
from mechloop.model.schema import Model
from mechloop.model.units import UnitProblem, unit_factor


class Builder(InputSteps, DyadSteps, TriadSteps, BodySteps, DimensionSteps):
    """Turns a :class:`GroupMechanism` into a :class:`BuiltModel`: the input, the groups in
    file order, the points left, then the model's data, checked."""

    # -- the mechanism -------------------------------------------------------------------

    def run(self) -> BuiltModel:
        """The checked vector model with its point locations and carriers."""
        mech = self.mech
        data = self.vector_data()
        try:
            model = Model.model_validate(data)
        except ValidationError as exc:  # pragma: no cover - a builder mistake
            raise ModelError([Problem(tuple(e["loc"]), e["msg"], "report this: the "
                                      "generated model is invalid") for e in exc.errors()]
                             ) from None
        _, problems = check_model(model)
        if problems:
            raise ModelError(problems)
        return BuiltModel(model, {k: v.body for k, v in self.links.items()},
                          self.locations(), self.carriers(), mech.formula)

    def vector_data(self) -> dict[str, Any]:
        """The plain data of the vector model, before it is validated and checked; every
        problem of the group file raised at once."""
        mech = self.mech
        self.declare()
        for kind in ("angle", "length"):
            try:
                factor = unit_factor(getattr(self.units, kind), kind)
            except UnitProblem as exc:
                raise ModelError([Problem(("units", kind), exc.message, exc.hint)]) from None
            if kind == "angle":
                self.half = math.pi / factor
        self.links[GROUND] = _Link(GROUND, 0, None, 0.0, {}, None, None)
        for name, (x, y) in mech.ground.items():
            z = complex(self.num(x, "length", ("ground", name, 0)),
                        self.num(y, "length", ("ground", name, 1)))
            self.coords[name] = z
            self.links[GROUND].local[name] = z
            self.new_point(name, (GROUND,), name, ())
        self.add_input()
        for i, group in enumerate(mech.groups):
            self.add_group(i, group)
        for name in list(self.pending):
            spec = self.pending.pop(name)
            if spec.link == GROUND:
                self.problems.append(Problem(("points", name, "link"), "a fixed point is a "
                                             "ground point", f"move {name} under ground: "
                                             "with its coordinates [x, y]"))
            else:
                self.problems.append(Problem(("points", name, "link"),
                                             f"no link named {spec.link!r}",
                                             _choose(spec.link, list(self.link_names))))
        for name in mech.masses:
            self.link_of(name, ("masses", name))
        if self.problems:
            raise ModelError(self.problems)
        self.close_loose_ends()
        data = self.model_data()
        if mech.synthesis is not None:
            data["synthesis"] = self.synthesis(mech.synthesis)
        if self.problems:
            raise ModelError(self.problems)
        return data

    def add_group(self, i: int, g: Any) -> None:
        kind = KIND[g.kind]
        path: tuple = ("groups", i)
        dim = f"groups[{i}]"
        if isinstance(g, Triad):
            before = len(self.problems)
            if not self.add_triad(g, path, dim) or len(self.problems) > before:
                for link in g.links:
                    if link not in self.links:
                        self.new_link(link, None, 0.0, {}, None, None)
                for leg in g.legs:
                    if leg.joint not in self.points:
                        self.new_point(leg.joint, (leg.link, g.link), self.root, (),
                                       broken=True)
            for link in g.links:
                self.add_points(link)
            return
        l1, l2 = g.links
        if g.variant == 2 and kind in ("L3", "L4", "L5"):
            why = {"L3": "its slide passes through the guide's pivot",
                   "L4": "its two slides meet in one point",
                   "L5": "its slot and guide meet in one point"}[kind]
            self.problems.append(Problem((*path, "variant"), f"an {kind} group has one "
                                         f"assembly ({why})", "remove variant (or write 1)"))
        variant: Variant = 1 if kind in ("L3", "L4", "L5") else g.variant
        new = getattr(g, "joint", None) or getattr(g, "point", None)
        before = len(self.problems)
        built = getattr(self, f"_{kind.lower()}")(g, path, dim, l1, l2, variant)
        if not built or len(self.problems) > before:
            for link in (l1, l2):
                if link not in self.links:
                    self.new_link(link, None, 0.0, {}, None, None)
            if new is not None and new not in self.points:
                self.new_point(new, (l1, l2), self.root, (), broken=True)
        for link in (l1, l2):
            self.add_points(link)

    def close_loose_ends(self) -> None:
        """Pl1 contours for the input and the points of links that no group used."""
        joint = self.points[self.mech.input.joint] if self.mech.input is not None else None
        if joint is not None and any(self.segs[s].vector is None for s, _ in joint.path):
            closer = self.seg(f"closing {joint.name}{joint.ground}", joint.name, joint.ground,
                              ("function",), ("function",), GROUND)
            self.contour([*joint.path, (closer, +1)], start=self.start_at(joint.ground),
                         name=f"input {self.mech.input.link}")
        for name in self.mech.points:
            point = self.points.get(name)
            if point is None or point.broken:
                continue
            seg_id, _ = point.path[-1]
            seg = self.segs[seg_id]
            if seg.vector is None:
                self.closing(seg_id, self.handle(seg.tail), f"point {name}")
