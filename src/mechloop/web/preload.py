"""Imported once by the fork server of the solves (:mod:`mechloop.web.worker`): loads
mechloop and solves a bundled example (kinematics and dynamics), so that numba's compiled
code is loaded into the fork server and every child starts with it, instead of loading it
from the disk cache again for each solve (about a second)."""

from __future__ import annotations

from mechloop.bundled.catalog import find_example
from mechloop.errors import MechloopError
from mechloop.model.load import load_model
from mechloop.web import app  # noqa: F401 (the routes' functions, run in the children)
from mechloop.web.payload import solution

for _name in ("crank_slider", "crank_slider_dynamics"):
    try:
        solution(load_model(find_example(_name).path))
    except MechloopError:  # only a warm-up: the real solves report their own problems
        pass
