"""Names in a group file: every point and link declared once, and a point reference
(``NAME`` or ``LINK.NAME``) resolved to the point on the link meant — with a located
problem and the names to choose from when it is not there (yet).
"""

from __future__ import annotations

from typing import Any

from mechloop.errors import Problem, format_path
from mechloop.model.groups.core import GROUND, BuilderCore, _choose, _Link, _Point
from mechloop.model.groups.spec import Triad


class NameSteps(BuilderCore):
    """Declares and resolves the names of points and links."""

    def declare(self) -> None:
        """Record every point name and where it is defined, and every link name."""
        self.declared = self._declared()

    # -- names ---------------------------------------------------------------------------

    def _declared(self) -> dict[str, tuple[str, tuple]]:
        """Every point name and where it is defined ("ground", "input", "groups[i]",
        "points")."""
        mech = self.mech
        out: dict[str, tuple[str, tuple]] = {}

        def add(name: str, what: str, path: tuple) -> None:
            if name in out:
                self.problems.append(Problem(path, f"point {name!r} is already defined at "
                                             f"{format_path(out[name][1])}",
                                             "give every point its own name"))
            else:
                out[name] = (what, path)

        for name in mech.ground:
            add(name, "ground", ("ground", name))
        if mech.input is not None:
            add(mech.input.joint, "input", ("input", "joint"))
        for i, g in enumerate(mech.groups):
            if isinstance(g, Triad):
                for j, leg in enumerate(g.legs):
                    add(leg.joint, f"groups[{i}]", ("groups", i, "legs", j, "joint"))
                continue
            new = getattr(g, "joint", None) or getattr(g, "point", None)
            if new is not None:
                key = "joint" if hasattr(g, "joint") else "point"
                add(new, f"groups[{i}]", ("groups", i, key))
        for name in mech.points:
            add(name, "points", ("points", name))
        names: dict[str, tuple] = {}
        inputs = [] if mech.input is None else [(mech.input.link, ("input", "link"))]
        for link, path in inputs + [
                (name, _link_path(g, i, j)) for i, g in enumerate(mech.groups)
                for j, name in enumerate(g.links)]:
            if link == GROUND:
                self.problems.append(Problem(path, "'ground' names the fixed link",
                                             "give the link another name"))
            elif link in names:
                self.problems.append(Problem(path, f"link {link!r} is already defined at "
                                             f"{format_path(names[link])}",
                                             "give every link its own name"))
            else:
                names[link] = path
        self.link_names = names
        return out

    def resolve(self, ref: str, path: tuple) -> _Point | None:
        """The point a reference names (on the asked link); a problem and None otherwise.
        Returns the point with ``links`` narrowed to the one meant (``links[0]``)."""
        link: str | None = None
        name = ref.strip()
        if "." in name:
            link, name = (s.strip() for s in name.split(".", 1))
            if link != GROUND and link not in self.link_names:
                self.problems.append(Problem(path, f"no link named {link!r}",
                                             _choose(link, [GROUND, *self.link_names])))
                return None
        if name not in self.declared:
            self.problems.append(Problem(path, f"unknown point {name!r}", _choose(
                name, [*self.points, *(p for p in self.declared if p not in self.points)],
                "the ground points, the input's joint, joints of earlier groups and points "
                "on links")))
            return None
        if name not in self.points:
            where, at = self.declared[name]
            if where == "points":
                on = self.mech.points[name].link
                defined = self.link_names.get(on)
                fix = (f"point {name} is on link {on!r}, defined at {format_path(defined)}: "
                       "attach this group after that one" if defined is not None else
                       f"point {name} is on link {on!r}, which no group defines")
            else:
                fix = (f"{name} is defined by {where} ({format_path(at)}): a group can only "
                       "use points of the ground, the input and earlier groups — move this "
                       "group after that one")
            self.problems.append(Problem(path, f"point {name!r} is not defined yet", fix))
            return None
        point = self.points[name]
        if point.broken:
            return None
        if link is None:
            if len(point.owners) > 1:
                options = " or ".join(f"{k}.{name}" for k in point.owners)
                self.problems.append(Problem(path, f"point {name!r} joins links "
                                             f"{' and '.join(point.owners)}: which one is "
                                             "meant is not clear", f"write {options}"))
                return None
            link = point.owners[0]
        if link not in point.links:
            self.problems.append(Problem(path, f"point {name!r} is not on link {link!r}",
                                         f"{name} is on {', '.join(point.links)}"))
            return None
        return _Point(point.name, point.owners, [link], point.ground, point.path)

    def _attach(self, refs: list[tuple[str, tuple]]) -> list[_Point] | None:
        out = [self.resolve(ref, p) for ref, p in refs]
        if any(p is None for p in out):
            return None
        names = [p.name for p in out if p is not None]
        if len(set(names)) < len(names):
            self.problems.append(Problem(refs[-1][1], f"both attachments are {names[0]}",
                                         "attach the group's links at two different points"))
            return None
        return out  # type: ignore[return-value]

    def link_of(self, name: str, path: tuple) -> _Link | None:
        if name in self.links and name != GROUND:
            return self.links[name]
        self.problems.append(Problem(path, f"no moving link named {name!r}",
                                     _choose(name, [k for k in self.links if k != GROUND])))
        return None


def _link_path(group: Any, i: int, j: int) -> tuple:
    """Where link ``j`` of ``group`` (number ``i``) is named in the document."""
    if isinstance(group, Triad):
        legs = [k for k, leg in enumerate(group.legs) if leg.link is not None]
        return ("groups", i, "legs", legs[j], "link") if j < len(legs) else ("groups", i, "link")
    return ("groups", i, "links", j)
