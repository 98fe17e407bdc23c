"""The blocks of a model with spatial contours (issue 17): contours solved alone by their
module, or together as a coupled block.

Every contour owns its functions (3 for a spatial contour, 2 for a planar one), and needs
the contours whose functions its links read.  The strongly connected components of that
graph, in dependency order, are the blocks (:func:`mechloop.model.structure._components`,
the planar analysis's decomposition): a component of several contours, or one contour
linking to one of its own functions (a non-elementary module), is *coupled* — its raw
closure equations are solved together by Newton's method
(:func:`mechloop.spatial.block.solve_coupled`); any other contour is solved alone by its
module Pr1–Pr19 or Pl1–Pl4.  A coupled block's unknowns are its contours' functions in
contour order (the columns of the block Jacobian: ``variant`` 1 is the assembly with a
negative determinant, 2 a positive one, ``auto`` variant 1 followed by continuity); its
contours may carry a ``guess`` of some of them (the assembly nearest to it).
"""

from __future__ import annotations

from mechloop.errors import Problem
from mechloop.model.block_guess import read_guess
from mechloop.model.schema import Model
from mechloop.model.structure import COUPLED, BlockInfo, ContourInfo, _components


def coupled_blocks(model: Model, infos: list[ContourInfo],
                   closed_only: dict[int, list[Problem]], problems: list[Problem]
                   ) -> tuple[tuple[ContourInfo, ...], tuple[BlockInfo, ...]]:
    """The contours with ``block`` (and ``module`` ``coupled`` in a coupled block) set, and
    the blocks in solving order.  ``closed_only`` are the problems of a contour that apply
    only when it is solved alone by its module (its ``variant`` beyond the module's
    branches, a ``guess``, Pr20's three rotations); they join ``problems`` for such a
    contour, and a coupled block's ``variant`` and ``guess`` are checked instead."""
    numbers = [info.number for info in infos]
    needs = {info.number: set(info.needs) - {info.number} for info in infos}
    groups = _components(numbers, needs)
    block_of = {n: i + 1 for i, group in enumerate(groups) for n in group}
    by_number = {info.number: info for info in infos}
    final: list[ContourInfo] = []
    blocks: list[BlockInfo] = []
    for i, group in enumerate(groups):
        coupled = len(group) > 1 or group[0] in by_number[group[0]].needs
        unknowns = tuple(f for n in group for f in by_number[n].functions)
        guess: dict[str, float] = {}
        for n in group:
            if not coupled:
                problems.extend(closed_only.get(n, []))
                continue
            contour = model.contours[n - 1]
            if contour.variant not in (1, 2, "auto"):
                problems.append(Problem(("contours", n - 1, "variant"), f"contour {n} is "
                                        "solved in a coupled block, whose variant is 1 (a "
                                        "negative Jacobian determinant) or 2 (positive); "
                                        f"variant {contour.variant!r} does not apply",
                                        "set 'variant' to 1, 2 or 'auto'"))
            read_guess(model, n, group, unknowns, guess, problems)
        variant = next((by_number[n].variant for n in group if by_number[n].variant != 1), 1)
        blocks.append(BlockInfo(number=i + 1, contours=tuple(group), unknowns=unknowns,
                                needs=tuple(sorted({block_of[m] for n in group
                                                    for m in needs[n]} - {i + 1})),
                                coupled=coupled, variant=variant, guess=guess))
        for n in group:
            info = by_number[n]
            fields = {k: getattr(info, k) for k in ("number", "vectors", "functions",
                                                    "module", "variant", "needs",
                                                    "arguments", "links")}
            if coupled:
                fields["module"] = COUPLED
            final.append(ContourInfo(**fields, block=i + 1))  # type: ignore[arg-type]
    final.sort(key=lambda c: c.number)
    return tuple(final), tuple(blocks)
