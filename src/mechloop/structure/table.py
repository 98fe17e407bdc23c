"""The identification table of a mechanism's structure (seed 002, table 1.6).

One row per group in attaching order (index ``group`` 1, 2, …; the seed's table 1.6
happens to list its groups by kind, which is also its order of L numbers), with the
seed's columns:

* ``L`` — the kind: 0 for an input group, 1…5 for the dyads L1…L5; the class in Roman
  numerals (``'III'``) for a group of a higher class, ``'?'`` for links left over;
* ``pairs`` — the pair letters of :class:`~mechloop.structure.assur.Group` (not in the
  seed; it helps to read the row);
* ``i-1``, ``j-1`` — the links that ``i`` and ``j`` are attached to by their external pairs
  (the guide of a P pair). For an input group moved by a cylinder, ``j-1`` is the link
  carrying the cylinder's other end;
* ``i``, ``j`` — the links of the group (an input link is ``i``); a group of more than two
  links lists them all in ``i``;
* ``i+1``, ``j+1`` — the links of later groups hinged (R) to ``i`` / ``j``: the links whose
  attachment points the seed marks on ``i`` and ``j`` (a link guided by ``i`` through a P
  pair is not listed, as in the seed); several are written ``"2,4"``;
* ``variant`` — the assembly variant, from the vector model.

Absent entries are ``"-"``, as in the seed.  The seed's last column, the code of the output
parameter, is not reproduced: its definition is lost from the seed's text.
"""

from __future__ import annotations

import pandas as pd

from mechloop.structure.assur import Decomposition, Group

COLUMNS = ["L", "pairs", "i-1", "j-1", "i", "j", "i+1", "j+1", "variant"]
NONE = "-"


def identification_table(decomposition: Decomposition) -> pd.DataFrame:
    """The identification table of ``decomposition`` (layout of the seed's table 1.6)."""
    rows = []
    groups = decomposition.groups
    for k, group in enumerate(groups):
        later = groups[k + 1:]
        rows.append(_row(group, later))
    if decomposition.rest:
        rows.append({"L": "?", "pairs": NONE, "i-1": NONE, "j-1": NONE,
                     "i": ",".join(map(str, decomposition.rest)), "j": NONE, "i+1": NONE,
                     "j+1": NONE, "variant": NONE})
    frame = pd.DataFrame(rows, columns=COLUMNS, dtype=object)
    frame.index = pd.RangeIndex(1, len(rows) + 1, name="group")
    return frame


def _row(group: Group, later: tuple[Group, ...]) -> dict[str, object]:
    def hinged(link: int | None) -> object:
        if link is None:
            return NONE
        found = sorted(p.link for g in later for p in g.external if p.to == link
                       and p.kind == "R")
        if not found:
            return NONE
        return found[0] if len(found) == 1 else ",".join(map(str, found))

    def given(value: int | None) -> object:
        return NONE if value is None else value

    variant = NONE if group.variant is None else group.variant
    if group.kind.startswith("L") and len(group.links) <= 2:
        i = group.links[0]
        j = group.links[1] if len(group.links) == 2 else None
        j_before = group.partner(j) if j is not None else None
        if group.kind == "L0" and j is None:
            j_before = next((k for ends in group.cylinders for k in ends if k != i), None)
        return {"L": int(group.kind[1:]), "pairs": group.pairs, "i-1": given(group.partner(i)),
                "j-1": given(j_before), "i": i, "j": given(j), "i+1": hinged(i),
                "j+1": hinged(j), "variant": variant}
    return {"L": 0 if group.kind == "L0" else group.kind, "pairs": group.pairs,
            "i-1": NONE, "j-1": NONE, "i": ",".join(map(str, group.links)), "j": NONE,
            "i+1": NONE, "j+1": NONE, "variant": variant}

