"""Structure: mobility and Assur groups of a planar mechanism (seed 002, DESIGN §6).

Owns the structural analysis of the link/pair graph of a
:class:`~mechloop.dynamics.mechanism.Mechanism` (links = the ground 0 and the moving bodies,
lower pairs, drives):

* :mod:`.mobility` — Chebyshev's mobility ``W = 3n − 2p5 − p4`` compared with the number
  of inputs, with an explanation when they differ;
* :mod:`.assur` — the decomposition into input groups L0 and Assur groups (class II of
  the five kinds L1 RRR, L2 RRP, L3 RPR, L4 PRP, L5 RPP, and groups of higher classes),
  the structure formula and the class of the mechanism;
* :mod:`.table` — the identification table of the seed (table 1.6 layout);
* :mod:`.analysis` — all of it for a model: solve, build the mechanism, analyse.

May import the model, the solver and ``mechloop.dynamics.mechanism``; nothing imports it
but the CLI.
"""

from mechloop.structure.analysis import analyze
from mechloop.structure.assur import Decomposition, Group, GroupPair, decompose
from mechloop.structure.mobility import Mobility, mobility
from mechloop.structure.table import identification_table

__all__ = [
    "Decomposition",
    "Group",
    "GroupPair",
    "Mobility",
    "analyze",
    "decompose",
    "identification_table",
    "mobility",
]
