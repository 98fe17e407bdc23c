"""Slow, independent oracles for the fast vectorized paths of mechloop (STYLE point 9).

An oracle never calls the code it checks: it reads the model's data (roles, contours,
arguments) and recomputes the answer the plain way, one position at a time.
"""
