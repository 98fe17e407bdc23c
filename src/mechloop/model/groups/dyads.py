"""The class-II groups (dyads) L1 RRR, L2 RRP, L3 RPR, L4 PRP and L5 RPP of a group file,
each written as one contour solved by an elementary module (Pl4, Pl3, Pl1, Pl2, Pl2).
"""

from __future__ import annotations

import math

from mechloop.errors import Problem
from mechloop.model.groups.places import PlaceSteps
from mechloop.model.groups.spec import PRP, RPP, RPR, RRP, RRR, Variant


class DyadSteps(PlaceSteps):
    """Builds the dyads."""

    def _l1(self, g: RRR, path: tuple, dim: str, l1: str, l2: str, variant: Variant) -> bool:
        len1 = self.num(g.lengths[0], "length", (*path, "lengths", 0), positive=True,
                        dim=f"{dim}.lengths[0]")
        len2 = self.num(g.lengths[1], "length", (*path, "lengths", 1), positive=True,
                        dim=f"{dim}.lengths[1]")
        got = self._attach([(g.at[0], (*path, "at", 0)), (g.at[1], (*path, "at", 1))])
        if got is None:
            return False
        p1, p2 = got
        b = g.joint
        u = self.seg(f"{l1} {p1.name}{b}", p1.name, b, ("const", len1, f"{dim}.lengths[0]"),
                     ("function",), l1)
        w = self.seg(f"{l2} {b}{p2.name}", b, p2.name, ("const", len2, f"{dim}.lengths[1]"),
                     ("function",), l2)
        self.loop((p1.ground, p1.path), [(u, +1), (w, +1)], (p2.ground, p2.path),
                  name=f"L1 {l1}-{l2}", variant=variant, module="Pl4")
        self.new_link(l1, u, 0.0, {p1.name: 0j, b: complex(len1)}, p1.name, b)
        self.new_link(l2, w, self.half, {p2.name: 0j, b: complex(len2)}, p2.name, b)
        self.links[l1].segments.append(u)
        self.links[l2].segments.append(w)
        via1 = (p1.ground, (*p1.path, (u, +1)))
        via2 = (p2.ground, (*p2.path, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (l1, l2), ground, chain)
        self.pins += [(p1.name, p1.links[0], l1, u, "tail"), (b, l1, l2, u, "head"),
                      (p2.name, p2.links[0], l2, w, "head")]
        return True

    def _l2(self, g: RRP, path: tuple, dim: str, rod: str, slider: str,
            variant: Variant) -> bool:
        length = self.num(g.length, "length", (*path, "length"), positive=True,
                          dim=f"{dim}.length")
        guide = self.guide(g.guide, (*path, "guide"), f"{dim}.guide")
        got = self._attach([(g.at, (*path, "at"))])
        if got is None or guide is None:
            return False
        (p1,), (through, angle, offset) = got, guide
        b = g.joint
        u = self.seg(f"{rod} {p1.name}{b}", p1.name, b, ("const", length, f"{dim}.length"),
                     ("function",), rod)
        s = self.seg(f"{slider} {b} along guide", b, ".foot", ("function",),
                     self.angle_on(through.links[0], angle + self.half, f"{dim}.guide.angle"),
                     slider, held={"tail": slider, "head": through.links[0]})
        side2 = self.guide_chain(through, offset, s, -90.0, f"{dim}.guide",
                                 f"guide offset of {slider}")
        self.loop((p1.ground, p1.path), [(u, +1), (s, +1)], (through.ground, side2),
                  name=f"L2 {rod}-{slider}", variant=variant, module="Pl3")
        self.new_link(rod, u, 0.0, {p1.name: 0j, b: complex(length)}, p1.name, b)
        self.new_link(slider, s, self.half, {b: 0j}, b, None)
        self.links[rod].segments.append(u)
        self.links[slider].segments.append(s)
        via1 = (p1.ground, (*p1.path, (u, +1)))
        via2 = (through.ground, (*side2, (s, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (rod, slider), ground, chain)
        self.pins += [(p1.name, p1.links[0], rod, u, "tail"), (b, rod, slider, u, "head")]
        self.slides.append((f"S{b}", through.links[0], slider, s, s, "tail"))
        return True

    def _l3(self, g: RPR, path: tuple, dim: str, block: str, lever: str,
            variant: Variant) -> bool:
        got = self._attach([(g.at[0], (*path, "at", 0)), (g.at[1], (*path, "at", 1))])
        if got is None:
            return False
        p1, p2 = got
        v = self.seg(f"{block}/{lever} {p1.name}{p2.name}", p1.name, p2.name, ("function",),
                     ("function",), lever, held={"tail": block, "head": lever})
        self.loop((p1.ground, p1.path), [(v, +1)], (p2.ground, p2.path),
                  name=f"L3 {block}-{lever}", variant=variant, module="Pl1")
        self.new_link(block, v, self.half, {p1.name: 0j}, p1.name, None)
        self.new_link(lever, v, self.half, {p2.name: 0j}, p2.name, None)
        self.links[block].segments.append(v)
        self.links[lever].segments.append(v)
        self.pins += [(p1.name, p1.links[0], block, v, "tail"),
                      (p2.name, p2.links[0], lever, v, "head")]
        self.slides.append((f"S{p1.name}", block, lever, v, v, "tail"))
        return True

    def _l4(self, g: PRP, path: tuple, dim: str, l1: str, l2: str, variant: Variant) -> bool:
        guide1 = self.guide(g.guides[0], (*path, "guides", 0), f"{dim}.guides[0]")
        guide2 = self.guide(g.guides[1], (*path, "guides", 1), f"{dim}.guides[1]")
        if guide1 is None or guide2 is None:
            return False
        (t1, angle1, off1), (t2, angle2, off2) = guide1, guide2
        b = g.joint
        u = self.seg(f"{l1} along guide to {b}", ".foot1", b, ("function",),
                     self.angle_on(t1.links[0], angle1, f"{dim}.guides[0].angle"), l1,
                     held={"tail": t1.links[0], "head": l1})
        w = self.seg(f"{l2} {b} along guide", b, ".foot2", ("function",),
                     self.angle_on(t2.links[0], angle2 + self.half, f"{dim}.guides[1].angle"),
                     l2, held={"tail": l2, "head": t2.links[0]})
        side1 = self.guide_chain(t1, off1, u, +90.0, f"{dim}.guides[0]",
                                 f"guide offset of {l1}")
        side2 = self.guide_chain(t2, off2, w, -90.0, f"{dim}.guides[1]",
                                 f"guide offset of {l2}")
        self.loop((t1.ground, side1), [(u, +1), (w, +1)], (t2.ground, side2),
                  name=f"L4 {l1}-{l2}", variant=variant, module="Pl2")
        self.new_link(l1, u, 0.0, {b: 0j}, b, None)
        self.new_link(l2, w, self.half, {b: 0j}, b, None)
        self.links[l1].segments.append(u)
        self.links[l2].segments.append(w)
        via1 = (t1.ground, (*side1, (u, +1)))
        via2 = (t2.ground, (*side2, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (l1, l2), ground, chain)
        self.slides.append((f"S{b}", t1.links[0], l1, u, u, "head"))
        self.pins.append((b, l1, l2, u, "head"))
        self.slides.append((f"S{b}", t2.links[0], l2, w, w, "tail"))
        return True

    def _l5(self, g: RPP, path: tuple, dim: str, block: str, yoke: str,
            variant: Variant) -> bool:
        guide = self.guide(g.guide, (*path, "guide"), f"{dim}.guide")
        slot = self.num(g.slot, "angle", (*path, "slot"), dim=f"{dim}.slot")
        got = self._attach([(g.at, (*path, "at"))])
        if got is None or guide is None:
            return False
        (p1,), (through, angle, offset) = got, guide
        if abs(math.sin(slot * math.pi / self.half)) < 1e-9:
            self.problems.append(Problem((*path, "slot"), "the slot runs along the guide, so "
                                         "the yoke's position along it is not determined",
                                         "give the slot an angle to the guide (90 for a "
                                         "Scotch yoke)"))
            return False
        point = g.point
        # P1 -> W back along the slot, W -> the guide's origin back along the guide
        w = self.seg(f"{yoke} {point} along guide", point, ".foot", ("function",),
                     self.angle_on(through.links[0], angle + self.half, f"{dim}.guide.angle"),
                     yoke, held={"tail": yoke, "head": through.links[0]})
        s = self.seg(f"{yoke} slot {p1.name}{point}", p1.name, point, ("function",),
                     ("link", w, "a", slot, f"{dim}.slot"), yoke,
                     held={"tail": block, "head": yoke})
        side2 = self.guide_chain(through, offset, w, -90.0, f"{dim}.guide",
                                 f"guide offset of {yoke}")
        self.loop((p1.ground, p1.path), [(s, +1), (w, +1)], (through.ground, side2),
                  name=f"L5 {block}-{yoke}", variant=variant, module="Pl2")
        self.new_link(block, s, self.half, {p1.name: 0j}, p1.name, None)
        self.new_link(yoke, w, self.half, {point: 0j}, point, None)
        self.links[block].segments.append(s)
        self.links[yoke].segments += [w, s]
        via1 = (p1.ground, (*p1.path, (s, +1)))
        via2 = (through.ground, (*side2, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(point, (yoke,), ground, chain)
        self.pins.append((p1.name, p1.links[0], block, s, "tail"))
        self.slides.append((f"S{p1.name}", block, yoke, s, s, "tail"))
        self.slides.append((f"S{point}", through.links[0], yoke, w, w, "tail"))
        return True
