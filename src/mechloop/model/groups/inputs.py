"""The input group L0 of a group file: a crank turning about a ground point or a slider
driven along a ground guide.
"""

from __future__ import annotations

from mechloop.errors import Problem
from mechloop.model.groups.places import PlaceSteps
from mechloop.model.groups.spec import GROUND, CrankInput


class InputSteps(PlaceSteps):
    """Builds the input group."""

    def add_input(self) -> None:
        spec = self.mech.input
        if spec is None:  # a triad's driven leg is the input
            return
        path = ("input",)
        if spec.argument not in self.mech.arguments:
            self.problems.append(Problem((*path, "argument"), f"argument {spec.argument} is "
                                         "not defined",
                                         f"add it under arguments: (e.g. {spec.argument}: "
                                         "{table: {0: 0, N: 360}}) or use one that exists"))
        if isinstance(spec, CrankInput):
            pivot = self.resolve(spec.pivot, (*path, "pivot"))
            length = self.num(spec.length, "length", (*path, "length"), positive=True,
                              dim="input.length")
            angle = self.num(spec.angle, "angle", (*path, "angle"), dim="input.angle")
            if pivot is not None and pivot.links[0] != GROUND:
                self.problems.append(Problem((*path, "pivot"), f"the crank's pivot {pivot.name} "
                                             "is not a ground point",
                                             "pivot the crank on a point of ground:"))
                pivot = None
            if pivot is None:
                self.new_point(spec.joint, (spec.link,), self.root, (), broken=True)
                self.new_link(spec.link, None, 0.0, {}, None, None)
                return
            crank = self.seg(f"{spec.link} {pivot.name}{spec.joint}", pivot.name, spec.joint,
                             ("const", length, "input.length"),
                             ("arg", spec.argument, angle, "input.angle"), spec.link)
            self.input_segs.add(crank)
            self.new_link(spec.link, crank, 0.0, {pivot.name: 0j, spec.joint: complex(length)},
                          pivot.name, spec.joint)
            self.links[spec.link].segments.append(crank)
            self.new_point(spec.joint, (spec.link,), pivot.ground,
                           (*pivot.path, (crank, +1)))
            self.pins.append((pivot.name, GROUND, spec.link, crank, "tail"))
        else:
            guide = self.guide(spec.guide, (*path, "guide"), "input.guide")
            shift = self.num(spec.shift, "length", (*path, "shift"), dim="input.shift")
            if guide is not None and guide[0].links[0] != GROUND:
                self.problems.append(Problem((*path, "guide", "through"), "the input slider's "
                                             "guide must be fixed in the ground",
                                             "run it through a ground point"))
                guide = None
            if guide is None:
                self.new_point(spec.joint, (spec.link,), self.root, (), broken=True)
                self.new_link(spec.link, None, 0.0, {}, None, None)
                return
            through, angle, offset = guide
            slide = self.seg(f"{spec.link} along guide to {spec.joint}", ".foot", spec.joint,
                             ("arg", spec.argument, shift, "input.shift"),
                             self.angle_on(GROUND, angle, "input.guide.angle"), spec.link,
                             held={"tail": GROUND, "head": spec.link})
            chain = self.guide_chain(through, offset, slide, +90.0, "input.guide",
                                     f"guide offset of {spec.link}")
            self.input_segs.update(s for s, _ in chain)
            self.input_segs.add(slide)
            self.new_link(spec.link, slide, 0.0, {spec.joint: 0j}, spec.joint, None)
            self.links[spec.link].segments.append(slide)
            self.new_point(spec.joint, (spec.link,), through.ground,
                           (*chain, (slide, +1)))
            self.slides.append((f"S{spec.joint}", GROUND, spec.link, slide, slide, "head"))
        self.add_points(spec.link)
