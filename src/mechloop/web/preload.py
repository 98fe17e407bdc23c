"""Imported once by the fork server of the solves (:mod:`mechloop.web.worker`): loads
mechloop and solves bundled examples (kinematics and dynamics, and a coupled block of
contours, whose first assembly takes SciPy's quasi-random starts), so that numba's compiled
code and SciPy are loaded into the fork server and every child starts with them, instead of
loading them again for each solve (about a second)."""

from __future__ import annotations

from mechloop.bundled.catalog import find_example
from mechloop.errors import MechloopError
from mechloop.model.load import load_model
from mechloop.web import app  # noqa: F401 (the routes' functions, run in the children)
from mechloop.web.payload import solution

for _name in ("crank_slider", "crank_slider_dynamics", "roof_support_real"):
    try:
        solution(load_model(find_example(_name).path))
    except MechloopError:  # only a warm-up: the real solves report their own problems
        pass
