"""Dynamics: masses, loads (springs and dampers: :mod:`.elements`), kinetostatics, reduced
characteristics, energy, machine motion and motion in time (speed-dependent loads there:
:mod:`.state_terms`; several inputs by Lagrange's equations: :mod:`.lagrange`, solved at
every state by :mod:`.state_kinematics`, integrated by :mod:`.simulate_inputs`).

Shared with models with spatial contours (:mod:`mechloop.spatial`): the walk placing the
contours from their starts (:mod:`.placing`), which bodies hold the vector ends and where
two bodies meet (:mod:`.holds`), a body's mass items and where their centres lie
(:mod:`.mass_items`)."""
