"""Which spatial module solves a contour, and running it with its branch chosen.

A spatial contour has three unknowns among the ``r, α, β`` of its vectors; which three
names the module of seed 000 table 2.1 (:data:`MODULES`): one vector with all three is
Pr1; one vector with two and another with one are Pr2–Pr10; three vectors with one each
are Pr11–Pr20.  :func:`classify` finds the module and the vectors ``i, j, k`` of its
formulas; :func:`run_module` calls it over the whole array of positions and returns every
branch; :func:`follow_branch` picks the branch a contour is on at every position — a fixed
variant, or continuity from position 0 (``auto``), fully vectorized.

Parameters are named by (vector number, letter) with letters ``r`` (length), ``a`` (α),
``b`` (β).  Knows nothing of model files.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.spatial.cone import solve_pr5, solve_pr6, solve_pr7
from mechloop.spatial.ellipses import solve_pr14, solve_pr15
from mechloop.spatial.horizontal import solve_pr18, solve_pr19
from mechloop.spatial.lengths import solve_pr11, solve_pr12, solve_pr13
from mechloop.spatial.octic import solve_pr16, solve_pr17
from mechloop.spatial.one_vector import solve_pr1
from mechloop.spatial.sphere import solve_pr8, solve_pr9, solve_pr10
from mechloop.spatial.vertical_plane import solve_pr2, solve_pr3, solve_pr4

Array = NDArray[np.float64]
Slot = tuple[int, str]  # (0, 1 or 2 for the module's vector i, j or k; "r" | "a" | "b")

#: module: (function, unknowns in the order it returns them, knowns in the order it takes
#: them after S, number of branches, takes ``convention``) — as tests/test_spatial_modules.
MODULES: dict[str, tuple[Callable[..., tuple[Array, ...]], list[Slot], list[Slot], int, bool]] = {
    "Pr1": (solve_pr1, [(0, "r"), (0, "a"), (0, "b")], [], 1, True),
    "Pr2": (solve_pr2, [(0, "r"), (0, "a"), (1, "r")], [(0, "b"), (1, "a"), (1, "b")], 1, False),
    "Pr3": (solve_pr3, [(0, "r"), (0, "a"), (1, "a")], [(0, "b"), (1, "r"), (1, "b")], 2, False),
    "Pr4": (solve_pr4, [(0, "r"), (0, "a"), (1, "b")], [(0, "b"), (1, "r"), (1, "a")], 2, False),
    "Pr5": (solve_pr5, [(0, "r"), (0, "b"), (1, "r")], [(0, "a"), (1, "a"), (1, "b")], 2, False),
    "Pr6": (solve_pr6, [(0, "r"), (0, "b"), (1, "a")], [(0, "a"), (1, "r"), (1, "b")], 4, False),
    "Pr7": (solve_pr7, [(0, "r"), (0, "b"), (1, "b")], [(0, "a"), (1, "r"), (1, "a")], 2, False),
    "Pr8": (solve_pr8, [(0, "a"), (0, "b"), (1, "r")], [(0, "r"), (1, "a"), (1, "b")], 2, True),
    "Pr9": (solve_pr9, [(0, "a"), (0, "b"), (1, "a")], [(0, "r"), (1, "r"), (1, "b")], 2, True),
    "Pr10": (solve_pr10, [(0, "a"), (0, "b"), (1, "b")], [(0, "r"), (1, "r"), (1, "a")], 2,
             True),
    "Pr11": (solve_pr11, [(0, "r"), (1, "r"), (2, "r")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "a"), (2, "b")], 1, False),
    "Pr12": (solve_pr12, [(0, "r"), (1, "r"), (2, "a")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "r"), (2, "b")], 2, False),
    "Pr13": (solve_pr13, [(0, "r"), (1, "r"), (2, "b")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "r"), (2, "a")], 2, False),
    "Pr14": (solve_pr14, [(0, "r"), (1, "a"), (2, "a")],
             [(0, "a"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "b")], 4, False),
    "Pr15": (solve_pr15, [(0, "r"), (1, "a"), (2, "b")],
             [(0, "a"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "a")], 4, False),
    "Pr16": (solve_pr16, [(0, "a"), (1, "a"), (2, "a")],
             [(0, "r"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "b")], 8, False),
    "Pr17": (solve_pr17, [(0, "a"), (1, "a"), (2, "b")],
             [(0, "r"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "a")], 8, False),
    "Pr18": (solve_pr18, [(0, "b"), (1, "b"), (2, "r")],
             [(0, "r"), (0, "a"), (1, "r"), (1, "a"), (2, "a"), (2, "b")], 2, False),
    "Pr19": (solve_pr19, [(0, "b"), (1, "b"), (2, "a")],
             [(0, "r"), (0, "a"), (1, "r"), (1, "a"), (2, "r"), (2, "b")], 4, False),
}

#: Pr2–Pr10 by (the two unknowns of vector i, the one of vector j).
_TWO = {("ra", "r"): "Pr2", ("ra", "a"): "Pr3", ("ra", "b"): "Pr4",
        ("rb", "r"): "Pr5", ("rb", "a"): "Pr6", ("rb", "b"): "Pr7",
        ("ab", "r"): "Pr8", ("ab", "a"): "Pr9", ("ab", "b"): "Pr10"}
#: Pr11–Pr20 by the sorted letters of the three unknowns: (module, letters of i, j, k).
_THREE = {"rrr": ("Pr11", "rrr"), "arr": ("Pr12", "rra"), "brr": ("Pr13", "rrb"),
          "aar": ("Pr14", "raa"), "abr": ("Pr15", "rab"), "aaa": ("Pr16", "aaa"),
          "aab": ("Pr17", "aab"), "bbr": ("Pr18", "bbr"), "abb": ("Pr19", "bba"),
          "bbb": ("Pr20", "bbb")}
_ORDER = "rab"


@dataclass(frozen=True)
class ModuleChoice:
    """A contour's module: its name, the vector numbers playing ``i, j, k`` (as many as the
    module uses) and the unknowns as (vector number, letter) in the module's order."""

    module: str
    roles: tuple[int, ...]
    unknowns: tuple[tuple[int, str], ...]

    @property
    def branches(self) -> int:
        """Number of solution branches (0 for Pr20: a family, not solved)."""
        return MODULES[self.module][3] if self.module in MODULES else 0


def classify(unknowns: Sequence[tuple[int, str]]) -> ModuleChoice | None:
    """The module of a contour whose three unknowns are ``unknowns`` ((vector number,
    letter) in contour order), or None when they are not three distinct parameters."""
    if len(unknowns) != 3 or len(set(unknowns)) != 3:
        return None
    by_vector: dict[int, str] = {}
    for number, letter in unknowns:
        by_vector[number] = by_vector.get(number, "") + letter
    by_vector = {n: "".join(sorted(s, key=_ORDER.index)) for n, s in by_vector.items()}
    vectors = list(by_vector)
    if len(vectors) == 1:
        (n,) = vectors
        roles: tuple[int, ...] = (n,)
        module = "Pr1"
    elif len(vectors) == 2:
        i = next(n for n in vectors if len(by_vector[n]) == 2)
        j = next(n for n in vectors if n != i)
        module, roles = _TWO[(by_vector[i], by_vector[j])], (i, j)
    else:
        key = "".join(sorted(by_vector[n] for n in vectors))
        module, letters = _THREE[key]
        left = list(vectors)
        picked = []
        for letter in letters:
            n = next(v for v in left if by_vector[v] == letter)
            left.remove(n)
            picked.append(n)
        roles = tuple(picked)
    if module == "Pr20":
        order = ((roles[0], "b"), (roles[1], "b"), (roles[2], "b"))
    else:
        order = tuple((roles[v], letter) for v, letter in MODULES[module][1])
    return ModuleChoice(module, roles, order)


def run_module(choice: ModuleChoice, s: tuple[Array, Array, Array],
               known: Mapping[tuple[int, str], Array | float], *, convention: int = 1
               ) -> tuple[tuple[Array, ...], NDArray[np.bool_]]:
    """Every branch of the module: the unknowns in ``choice.unknowns`` order, each shape
    ``(B, ..., P)``, and ``ok`` ``(B, ..., P)``.  ``s`` is the sum of the known vectors,
    ``known`` the known parameters of the vectors ``i, j, k`` (SI)."""
    fn, _, knowns, _, conv = MODULES[choice.module]
    args = [known[(choice.roles[v], letter)] for v, letter in knowns]
    kwargs = {"convention": convention} if conv else {}
    *values, ok = fn(*s, *args, **kwargs)
    return tuple(values), ok


def follow_branch(points: Array, ok: NDArray[np.bool_], start: int) -> NDArray[np.int64]:
    """The branch (0-based index) at every position of the path that starts on branch
    ``start`` (0-based) at position 0 and moves continuously.

    ``points`` ``(B, C, ..., P)``: per branch, ``C`` Cartesian coordinates that the
    unknowns move (comparable distances); ``ok`` ``(B, ..., P)``.  Between two positions
    each existing branch goes on to the nearest existing branch of the next position
    (roots sorted by value change labels where others appear or vanish), the branches
    with no continuation to the labels left over, in order; where two branches would go
    to the same one (they meet) the labels are kept.  The steps are
    composed by a parallel prefix scan (``log₂ P`` vectorized rounds, no loop over
    positions).  Returns ``(..., P)``.
    """
    n_branch = points.shape[0]
    lead = points.shape[2:]
    if n_branch == 1 or lead[-1] < 2:
        return np.full(lead, start, dtype=np.int64)
    prev, nxt = points[..., :-1], points[..., 1:]
    # dist[b, c, ..., p]: from branch b at p − 1 to branch c at p (both existing)
    with np.errstate(invalid="ignore"):
        dist = np.abs(prev[:, None] - nxt[None, :]).sum(axis=2)
    both = ok[:, None, ..., :-1] & ok[None, :, ..., 1:]
    dist = np.moveaxis(np.where(both & np.isfinite(dist), dist, np.inf), (0, 1), (-2, -1))
    pick = np.argmin(dist, axis=-1)  # (..., P−1, B): the nearest branch at p
    valid = np.isfinite(np.min(dist, axis=-1))
    labels = np.arange(n_branch)
    used = np.zeros(pick.shape, dtype=bool)
    unique = np.ones(pick.shape[:-1], dtype=bool)
    for b in range(n_branch):  # a loop over the branches (≤ 8), not over positions
        hits = np.count_nonzero(valid & (pick == b), axis=-1)
        unique &= hits <= 1
        used[..., b] = hits > 0
    # the branches with no continuation take the unused labels, in order of their labels
    free_from = np.argsort(np.where(valid, n_branch + labels, labels), axis=-1, kind="stable")
    free_to = np.argsort(np.where(used, n_branch + labels, labels), axis=-1, kind="stable")
    filler = np.empty_like(pick)
    np.put_along_axis(filler, free_from, free_to, axis=-1)
    step = np.where(valid, pick, filler)
    step = np.where(unique[..., None], step, labels)  # two meet: keep the labels
    first = np.broadcast_to(np.arange(n_branch), (*step.shape[:-2], 1, n_branch))
    comp = np.concatenate([first, step], axis=-2)  # (..., P, B): position p from p − 1
    shift = 1
    n_pos = comp.shape[-2]
    while shift < n_pos:
        later = comp[..., shift:, :]
        earlier = comp[..., :-shift, :]
        comp = np.concatenate([comp[..., :shift, :],
                               np.take_along_axis(later, earlier, axis=-1)], axis=-2)
        shift *= 2
    return comp[..., start]
