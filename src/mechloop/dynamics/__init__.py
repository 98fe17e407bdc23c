"""Dynamics: masses, loads (springs and dampers: :mod:`.elements`), kinetostatics, reduced
characteristics, energy, machine motion and motion in time (speed-dependent loads there:
:mod:`.state_terms`)."""
