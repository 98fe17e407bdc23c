"""Dynamics: masses, loads, kinetostatics, reduced characteristics, energy and machine motion."""
