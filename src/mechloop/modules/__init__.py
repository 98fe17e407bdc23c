"""Elementary modules: pure array functions that solve one closed contour.

Owns: Pl1–Pl4 (:mod:`.planar`), their compiled kernels (:mod:`.kernels`), and the
coupled block — contours solved together by Newton's continuation (:mod:`.coupled`,
numba).  Imports only NumPy, numba and SciPy; knows nothing of models or files.
"""
