"""Mobility of a planar mechanism by Chebyshev's formula (seed 002, step 5).

``W = 3n − 2p5 − p4``: ``n`` moving links, ``p5`` lower pairs (revolute and prismatic, the
pairs of the fifth class), ``p4`` higher pairs: the gear meshes, ratio links between two
bodies (:mod:`.meshes`).  A hydraulic cylinder (a ``length`` drive) is a driving pair
between the two bodies at its ends, not two more links: its cylinder and rod with their
three pairs would add ``3·2 − 2·3 = 0``, so W is the same either way.

W is compared with the number of inputs (the model arguments that move bodies).  When they
differ the seed asks to look for a mistake or for redundant constraints and passive links;
:func:`mobility` says which, using the decomposition (:mod:`.assur`) to point at the links.
"""

from __future__ import annotations

from dataclasses import dataclass

from mechloop.dynamics.mechanism import Mechanism
from mechloop.structure.assur import decompose, moving_links
from mechloop.structure.meshes import Mesh, replaced


@dataclass(frozen=True)
class Mobility:
    """Chebyshev's count: ``W = 3n − 2p5 − p4`` against ``inputs`` (drives), with the
    ``explanation`` of a mismatch (or of passive and free links found anyway)."""

    n: int
    p5: int
    p4: int
    W: int  # the textbook's symbol (Chebyshev)
    inputs: int
    explanation: str
    #: the higher pairs counted in ``p4``
    meshes: tuple[Mesh, ...] = ()

    @property
    def ok(self) -> bool:
        """W equals the number of inputs and is positive."""
        return self.W == self.inputs and self.W > 0

    def __str__(self) -> str:
        higher = ("no higher pairs in the model" if not self.meshes
                  else "; ".join(map(str, self.meshes)))
        return (f"n = {self.n}, p5 = {self.p5}, p4 = {self.p4} ({higher}"
                f"): W = 3·{self.n} − 2·{self.p5} − {self.p4} = {self.W}; inputs: "
                f"{self.inputs}. {self.explanation}")


def mobility(mechanism: Mechanism, meshes: tuple[Mesh, ...] = ()) -> Mobility:
    """Chebyshev's mobility of ``mechanism`` compared with its number of drives; ``meshes``
    are its higher pairs (``p4``), replaced by their equivalents for the notes.

    >>> from mechloop.dynamics.mechanism import Drive, Mechanism, Pair
    >>> from mechloop.model.dynamic import TailPoint
    >>> pin = lambda a, b: Pair(f"J{a}_{b}", "revolute", (a, b), TailPoint(tail=1), None,
    ...                         0.0, 0.0, 0.0, False)
    >>> five_bar = Mechanism({}, (), (pin(0, 1), pin(1, 2), pin(2, 3), pin(3, 4), pin(0, 4)),
    ...                      (Drive(1, "angle", 1, (0, 1)),), 0.0)
    >>> m = mobility(five_bar)
    >>> m.W, m.inputs, m.explanation.split(":")[0]
    (2, 1, 'W = 2 > 1 input(s)')
    """
    n = len(moving_links(mechanism))
    p5, p4 = len(mechanism.pairs), len(meshes)
    w = 3 * n - 2 * p5 - p4
    inputs = len(mechanism.drives)
    if w == inputs and w > 0:
        head = f"W = {w} equals the number of inputs"
    elif w > inputs:
        head = (f"W = {w} > {inputs} input(s): {w - inputs} input(s) missing — the mechanism "
                f"needs {w - inputs} more drive(s), or a link has a local mobility")
    elif inputs == 0:
        head = (f"W = {w} ≤ 0 and no inputs: a structure (a truss), not a mechanism"
                + (", with redundant constraints" if w < 0 else ""))
    else:
        head = (f"W = {w} < {inputs} input(s): redundant constraints (an over-constrained "
                "chain, a passive link) or more drives than the chain can take"
                + ("; W ≤ 0: the chain cannot move at all unless its geometry is special"
                   if w <= 0 else ""))
    notes = decompose(replaced(mechanism, meshes)[0]).notes
    if notes:
        head += (" — but: " if w == inputs else " — found: ") + "; ".join(notes)
    return Mobility(n, p5, p4, w, inputs, head + ".", tuple(meshes))
