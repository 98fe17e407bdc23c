"""Elementary modules: pure array functions that solve one closed contour.

Owns: Pl1–Pl4 (:mod:`.planar`).  Imports only NumPy; knows nothing of models or files.
"""
