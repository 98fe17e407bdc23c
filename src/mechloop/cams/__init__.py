"""Cam design by inverted motion (course sheet 4; seed 000 sec. 2.3–2.6).

Owns the follower motion laws (:mod:`.laws`), the motion program of segments
(:mod:`.program`), the followers (:mod:`.followers`), the profile synthesis (:mod:`.profile`),
the checks over the continuous cam angle (:mod:`.checks`), the smallest base radius
(:mod:`.base_radius`), a design with its figures (:mod:`.design`, :mod:`.summary`), the
``cam:`` document (:mod:`.document`), the files (:mod:`.export`) and the figures
(:mod:`.plots`).  It imports from ``mechloop.errors``, ``mechloop.model`` (the document
reader, numbers and units), ``mechloop.output`` (atomic files, table writers) and
``mechloop.views`` (figure and animation helpers) — never from the vector-model solver,
which the tests use as a second route to the same profile.

    >>> import math
    >>> from mechloop.cams import Cam, MotionProgram, Segment, TranslatingRoller, law
    >>> turn = MotionProgram((Segment("rise", math.pi, 0.02, law("cycloidal")),
    ...                       Segment("return", math.pi, 0.02, law("cycloidal"))))
    >>> cam = Cam(TranslatingRoller(roller_radius=0.01), turn, base_radius=0.04)
    >>> round(float(cam.at([0.0]).profile[0, 1]), 6)  # roller on the base circle at φ = 0
    0.03
"""

from mechloop.cams.base_radius import (
    CamDesignError,
    minimum_base_radius,
    minimum_flat_base_radius,
)
from mechloop.cams.design import CamDesign
from mechloop.cams.document import cam_from_data, cam_json_schema, load_cam
from mechloop.cams.followers import OscillatingRoller, TranslatingFlat, TranslatingRoller
from mechloop.cams.laws import LAW_NAMES, Law, law, peak_coefficients, table_law
from mechloop.cams.profile import Cam, Geometry
from mechloop.cams.program import MotionProgram, Segment

__all__ = ["LAW_NAMES", "Cam", "CamDesign", "CamDesignError", "Geometry", "Law",
           "MotionProgram", "OscillatingRoller", "Segment", "TranslatingFlat",
           "TranslatingRoller", "cam_from_data", "cam_json_schema", "law", "load_cam",
           "minimum_base_radius", "minimum_flat_base_radius", "peak_coefficients",
           "table_law"]
