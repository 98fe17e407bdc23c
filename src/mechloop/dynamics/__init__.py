"""Dynamics: masses, loads (springs and dampers: :mod:`.elements`), kinetostatics, reduced
characteristics, energy, machine motion and motion in time (speed-dependent loads there:
:mod:`.state_terms`; several inputs by Lagrange's equations: :mod:`.lagrange`, solved at
every state by :mod:`.state_kinematics`, integrated by :mod:`.simulate_inputs`)."""
