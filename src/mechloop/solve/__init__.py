"""Solving a model over all positions: inputs, contour order, kinematics, results.

Owns: model time and arguments as signals (:mod:`.inputs`), the kinematic solve
(:mod:`.kinematics`), :class:`~.results.Results`, and whether a solve fits in the machine's
memory (:mod:`.memory`).  Imports ``mechloop.model`` and
``mechloop.modules``; never the CLI or views.
"""
