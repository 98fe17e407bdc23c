"""Solving a model over all positions: inputs, contour order, kinematics, results.

Owns: model time and arguments as signals (:mod:`.inputs`), the kinematic solve
(:mod:`.kinematics`; a coupled block's parameters gathered for
:mod:`mechloop.modules.coupled` in :mod:`.blocks`), :class:`~.results.Results`, whether
a solve fits in the machine's memory (:mod:`.memory`), and whether a chain assembles
over the whole continuous input (:mod:`.existence`: the closed forms of crank-driven
loops in :mod:`.loop_forms`, any other loop between the positions in :mod:`.between`).
Imports ``mechloop.model`` and ``mechloop.modules``; never the CLI or views.
"""
