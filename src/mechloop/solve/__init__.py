"""Solving a model over all positions: inputs, contour order, kinematics, results.

Owns: model time and arguments as signals (:mod:`.inputs`), the kinematic solve
(:mod:`.kinematics`) and :class:`~.results.Results`.  Imports ``mechloop.model`` and
``mechloop.modules``; never the CLI or views.
"""
