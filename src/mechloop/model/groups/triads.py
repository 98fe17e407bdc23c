"""The class-III groups (triads) of a group file, written as a coupled block of two
contours.

A triad's middle (ternary) link carries the joints J1, J2, J3 of its three legs; a leg is
pinned to a placed point (an RR leg: its angle is unknown), slides along a ground guide
(a PR leg: its position along the guide is unknown) or is a hydraulic leg, a drive whose
length is an argument (its angle is unknown; the triad is then the mechanism's input
group, and the leg no link of it).  With the angle θ of the middle
link that makes four unknowns, and the two contours

* contour 1: the chain to J1 (leg 1), J1 → J2 on the middle link (θ), back along leg 2 —
  leg 2's vector here is a linked copy of the one contour 2 writes;
* contour 2: the chain to J2 (leg 2), J2 → J1 → J3 on the middle link (links to θ), back
  along leg 3,

each have two functions (leg 1 and θ; leg 2 and leg 3) and read one of the other's: no
elementary module solves either, the two are solved together (a coupled block, Newton's
method on the closure equations).  Each contour carries a ``guess`` of its functions at
position 0, computed from the approximate positions the file gives (``guess:``), which
picks the assembly among the triad's up to six.
"""

from __future__ import annotations

import cmath
import math
from typing import Any

from mechloop.errors import Problem
from mechloop.model.groups.core import GROUND, _tidy
from mechloop.model.groups.places import PlaceSteps
from mechloop.model.groups.spec import LegDrive, Triad


class TriadSteps(PlaceSteps):
    """Builds triads."""

    def add_triad(self, g: Triad, path: tuple, dim: str) -> bool:
        """Write triad ``g``: its links, joints, pins and slides, and its two contours with
        their guesses.  False (with the problems recorded) when it cannot be written."""
        sides = [self.num(g.sides[k], "length", (*path, "sides", k), positive=True,
                          dim=f"{dim}.sides[{k}]") for k in (0, 1)]
        gamma = self.num(g.angle, "angle", (*path, "angle"), dim=f"{dim}.angle")
        legs: list[tuple[Any, ...]] = []
        for j, leg in enumerate(g.legs):
            where, name = (*path, "legs", j), f"{dim}.legs[{j}]"
            if isinstance(leg.length, LegDrive):
                assert leg.at is not None  # TriadLeg checks
                drive = leg.length
                shift = self.num(drive.shift, "length", (*where, "length", "shift"),
                                 dim=f"{name}.length.shift")
                if drive.argument not in self.mech.arguments:
                    self.problems.append(Problem((*where, "length", "argument"),
                                                 f"argument {drive.argument} is not defined",
                                                 f"add it under arguments: (e.g. "
                                                 f"{drive.argument}: {{table: {{0: 1.0, N: "
                                                 "1.6}}) or use one that exists"))
                at = self.resolve(leg.at, (*where, "at"))
                legs.append(("D", at, drive.argument, shift) if at is not None else None)
                continue
            if leg.guide is None:
                assert leg.at is not None and leg.length is not None  # TriadLeg checks
                length = self.num(leg.length, "length", (*where, "length"), positive=True,
                                  dim=f"{name}.length")
                at = self.resolve(leg.at, (*where, "at"))
                legs.append(("R", at, length) if at is not None else None)
                continue
            guide = self.guide(leg.guide, (*where, "guide"), f"{name}.guide")
            if guide is not None and guide[0].links[0] != GROUND:
                self.problems.append(Problem((*where, "guide", "through"), "a triad's "
                                             "sliding leg runs along a ground guide here",
                                             "run the guide through a ground point (a "
                                             "guide on a moving link is not supported in "
                                             "a triad)"))
                guide = None
            legs.append(("P", *guide) if guide is not None else None)
        joints = [leg.joint for leg in g.legs]
        if len(set(joints)) < 3:
            self.problems.append(Problem((*path, "legs"), "two legs share a joint",
                                         "give each leg its own joint on the middle link"))
            return False
        guess = self._guess(g, path, legs)
        if any(leg is None for leg in legs) or guess is None:
            return False
        chains, unknowns = [], []
        for j, (leg, spec) in enumerate(zip(legs, g.legs, strict=True)):
            chain, seg = self._leg(j, leg, spec.link, spec.joint, dim)
            chains.append(chain)
            unknowns.append((seg, *self._leg_guess(leg, spec.joint, guess)))
        j1, j2, j3 = joints
        m12 = self.seg(f"{g.link} {j1}{j2}", j1, j2, ("const", sides[0], f"{dim}.sides[0]"),
                       ("function",), g.link)
        m13 = self.seg(f"{g.link} {j1}{j3}", j1, j3, ("const", sides[1], f"{dim}.sides[1]"),
                       ("link", m12, "a", gamma, f"{dim}.angle"), g.link)
        theta = cmath.phase(guess[j2] - guess[j1]) * self.half / math.pi
        seg2 = unknowns[1][0]
        tail, head = self.segs[seg2].tail, self.segs[seg2].head
        copy2 = self.seg(f"{g.legs[1].link or 'leg'} copy {tail}{head}", tail, head,
                         ("link", seg2, "r", 0.0, None), ("link", seg2, "a", 0.0, None),
                         g.legs[1].link or GROUND)
        ground2, chain2 = chains[1]
        self.loop(chains[0], [(m12, +1)], (ground2, (*chain2[:-1], (copy2, +1))),
                  name=f"III {g.link} 1", variant=1, module="coupled")
        self._put_guess([unknowns[0], (m12, "a", theta)])
        self.loop(chains[1], [(m12, -1), (m13, +1)], chains[2], name=f"III {g.link} 2",
                  variant=1, module="coupled")
        self._put_guess(unknowns[1:])
        local = {j1: 0j, j2: complex(sides[0]),
                 j3: sides[1] * cmath.exp(1j * gamma * math.pi / self.half)}
        for (seg, _, _), leg, spec in zip(unknowns, legs, g.legs, strict=True):
            if leg[0] == "D":  # a drive between its ends, not a link
                continue
            assert spec.link is not None
            if leg[0] == "R":
                at = leg[1]
                self.new_link(spec.link, seg, 0.0, {at.name: 0j, spec.joint: complex(leg[2])},
                              at.name, spec.joint)
                self.pins.append((at.name, at.links[0], spec.link, seg, "tail"))
            else:
                self.new_link(spec.link, seg, 0.0, {spec.joint: 0j}, spec.joint, None)
                self.slides.append((f"S{spec.joint}", GROUND, spec.link, seg, seg, "head"))
            self.links[spec.link].segments.append(seg)
        self.new_link(g.link, m12, 0.0, local, j1, j2)
        self.links[g.link].segments += [m12, m13]
        for (seg, _, _), (ground, chain), spec in zip(unknowns, chains, g.legs, strict=True):
            if spec.link is None:  # the driven leg's end: a point of the middle link
                self.new_point(spec.joint, (g.link,), ground, chain)
                continue
            self.new_point(spec.joint, (spec.link, g.link), ground, chain)
            self.pins.append((spec.joint, spec.link, g.link, seg, "head"))
        return True

    def _leg(self, j: int, leg: tuple[Any, ...], link: str | None, joint: str, dim: str
             ) -> tuple[tuple[str, tuple], int]:
        """The segment of leg ``j`` (to its joint) and the chain from the ground to the
        joint through it."""
        if leg[0] == "D":
            _, at, argument, shift = leg
            seg = self.seg(f"leg {at.name}{joint}", at.name, joint,
                           ("arg", argument, shift, f"{dim}.legs[{j}].length.shift"),
                           ("function",), GROUND)
            return (at.ground, (*at.path, (seg, +1))), seg
        assert link is not None
        if leg[0] == "R":
            _, at, length = leg
            seg = self.seg(f"{link} {at.name}{joint}", at.name, joint,
                           ("const", length, f"{dim}.legs[{j}].length"), ("function",), link)
            return (at.ground, (*at.path, (seg, +1))), seg
        _, through, angle, offset = leg
        seg = self.seg(f"{link} along guide to {joint}", f".foot{j}", joint, ("function",),
                       self.angle_on(GROUND, angle, f"{dim}.legs[{j}].guide.angle"), link,
                       held={"tail": GROUND, "head": link})
        chain = self.guide_chain(through, offset, seg, +90.0, f"{dim}.legs[{j}].guide",
                                 f"guide offset of {link}")
        return (through.ground, (*chain, (seg, +1))), seg

    def _leg_guess(self, leg: tuple[Any, ...], joint: str, guess: dict[str, complex]
                   ) -> tuple[str, float]:
        """The unknown of a leg's segment (``"a"`` or ``"r"``) and its value (model units)
        with the points at their ``guess`` positions."""
        if leg[0] in "RD":
            at = leg[1]
            start = self.coords[at.name] if at.links[0] == GROUND else guess[at.name]
            return "a", cmath.phase(guess[joint] - start) * self.half / math.pi
        _, through, angle, offset = leg
        turn = angle * math.pi / self.half
        foot = self.coords[through.name] + (offset or 0.0) * cmath.exp(1j * (turn + math.pi / 2))
        return "r", ((guess[joint] - foot) * cmath.exp(-1j * turn)).real

    def _guess(self, g: Triad, path: tuple, legs: list[tuple[Any, ...] | None]
               ) -> dict[str, complex] | None:
        """The approximate positions of ``g.guess`` (model units) after checking that they
        name the joints and the moving attachments, each once."""
        base = (*path, "guess")
        needed = [leg.joint for leg in g.legs] + [
            leg[1].name for leg in legs if leg is not None and leg[0] in "RD"
            and leg[1].links[0] != GROUND]
        out: dict[str, complex] = {}
        known = all(leg is not None for leg in legs)  # else the attachments are unknown
        for name, (x, y) in g.guess.items():
            if name not in needed:
                if known:
                    self.problems.append(Problem((*base, name), f"{name!r} is not a joint of "
                                                 "this triad or a moving point its legs are "
                                                 "pinned to", f"give approximate positions "
                                                 f"of {', '.join(needed)}"))
                continue
            out[name] = complex(self.num(x, "length", (*base, name, 0)),
                                self.num(y, "length", (*base, name, 1)))
        missing = [name for name in needed if name not in g.guess]
        if missing:
            self.problems.append(Problem((*base, missing[0]), f"no approximate position of "
                                         f"{', '.join(missing)}: a triad has up to six "
                                         "assemblies, and these pick one",
                                         f"add {missing[0]}: [x, y] (where it is at position "
                                         "0, roughly) under guess:"))
            return None
        return out

    def _put_guess(self, unknowns: list[tuple[int, str, float]]) -> None:
        """The last contour's ``guess``: each unknown of a segment as its written vector's
        parameter (an angle turned by half a turn when the vector is reversed)."""
        entry = self.contours[-1]
        guess = entry.setdefault("guess", {})
        for seg_id, letter, value in unknowns:
            seg = self.segs[seg_id]
            assert seg.vector is not None
            if letter == "a":
                value = _tidy(value + (self.half if seg.reversed else 0.0), self.half)
            guess[f"{letter}{seg.vector}"] = round(value, 12) + 0.0
