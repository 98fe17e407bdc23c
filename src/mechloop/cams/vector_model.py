"""The cam as the seed builds it: a vector model with intermediate arguments (seed 000
sec. 2.4, 2.6), written from a cam design, whose envelope is the cam profile.

In the cam's frame the follower's guide turns by ``−φ`` (argument 1, over positions
``0..360``, one per degree).  Each rise or return is an argument of its own — the model's
law from 0 to ``±h`` over the segment's positions, holding its end value after — driving
a vector along the guide, so the vectors along the guide add up to the displacement.  The
roller's radius vector turns through a full turn in every position (an intermediate
argument), and the envelope of the roller circles, branch −1, is the working profile; a
flat face is swept along its length instead, and its envelope is the profile.

Only translating followers (roller and flat) and the laws the vector model has
(``constant_speed``, ``harmonic``, ``cycloidal``, ``poly345``) can be written, with
segments that start at whole degrees: the model's arguments change one parameter each,
while a rocker's arm angle would be the sum of two (``−φ`` and ``ψ``).
"""

from __future__ import annotations

import math
from typing import Any

from mechloop.cams.base_radius import CamDesignError
from mechloop.cams.design import CamDesign
from mechloop.cams.followers import TranslatingFlat, TranslatingRoller

#: The laws of cam design that the vector model's arguments have too.
MODEL_LAWS = ("constant_speed", "harmonic", "cycloidal", "poly345")


def vector_model_data(design: CamDesign, *, sweep: int = 73) -> dict[str, Any]:
    """The vector model of ``design`` as plain data (a model file's content; lengths in
    m, angles in degrees, one position per degree of cam angle).  ``sweep``: values of
    the intermediate argument (around the roller, or along the face).

    Raises :class:`~mechloop.cams.base_radius.CamDesignError` for a follower or a law
    the vector model cannot express, or a segment that does not start at a whole degree.
    """
    follower = design.follower
    if not isinstance(follower, TranslatingRoller | TranslatingFlat):
        raise CamDesignError("only a translating follower can be written as a vector model",
                             "a rocker's arm angle is the sum of two arguments (−φ and ψ)")
    edges = [math.degrees(e) for e in design.program.edges]
    if any(abs(e - round(e)) > 1e-9 for e in edges):
        raise CamDesignError("the vector model needs segments that start at whole degrees",
                             "round the segment angles to whole degrees")
    arguments: dict[int, Any] = {1: {"table": {0: 0, 360: -360}}}
    vectors: dict[int, Any] = {}
    guide: list[int] = []
    number = 10
    flat = isinstance(follower, TranslatingFlat)
    start = design.cam.base_radius if flat else math.sqrt(
        design.cam.base_radius**2 - follower.offset**2)
    for k, seg in enumerate(design.program.segments):
        if seg.law is None:
            continue
        if seg.law.name not in MODEL_LAWS:
            raise CamDesignError(f"the vector model has no law {seg.law.name!r}",
                                 f"use one of {', '.join(MODEL_LAWS)}")
        arg = len(arguments) + 1
        arguments[arg] = {"law": seg.law.name, "start": [round(edges[k]), 0.0],
                          "end": [round(edges[k + 1]), seg.sign * seg.lift]}
        vectors[number] = {"r": {"argument": arg, "offset": start if not guide else 0.0},
                           "a": {"argument": 1, "offset": 90}, "name": f"{seg.kind} {k + 1}"}
        guide.append(number)
        number += 1
    if not guide:  # a program of dwells: the guide is a constant length
        vectors[number] = {"r": start, "a": {"argument": 1, "offset": 90}, "name": "guide"}
        guide.append(number)
    sweep_arg = len(arguments) + 1
    chain = list(guide)
    if flat:
        width = design.summary().face
        assert width is not None
        reach = 1.5 * max(abs(width.low.value), abs(width.high.value)) + 0.1 * start
        arguments[sweep_arg] = {"intermediate": {"from": -reach, "to": reach,
                                                 "count": sweep}}
        vectors[1] = {"r": {"argument": sweep_arg}, "a": {"argument": 1}, "name": "face"}
        chain.append(1)
    else:
        arguments[sweep_arg] = {"intermediate": {"from": 0, "to": 360, "count": sweep}}
        vectors[1] = {"r": follower.offset, "a": {"argument": 1}, "name": "offset"}
        vectors[2] = {"r": follower.roller_radius, "a": {"argument": sweep_arg},
                      "name": "roller"}
        chain = [1, *guide, 2]
    vectors[3] = {"r": "function", "a": "function", "name": "closing"}
    return {"name": f"{design.name or 'cam'} (vector model)",
            "units": {"length": "m", "angle": "deg"}, "positions": 360,
            "arguments": arguments, "vectors": dict(sorted(vectors.items())),
            "contours": [{"vectors": [*chain, 3]}],
            "envelopes": [{"name": "profile", "vectors": chain}]}


def write_vector_model(design: CamDesign, path, *, sweep: int = 73):
    """Write :func:`vector_model_data` of ``design`` as a model file (YAML, or JSON for
    ``.json``), atomically, after checking that it loads as a model."""
    import json
    from pathlib import Path

    import yaml

    from mechloop.model.load import model_from_data
    from mechloop.output.atomic import atomic_write_text

    data = vector_model_data(design, sweep=sweep)
    model_from_data(data)  # it is a valid model
    target = Path(path)
    header = (f"# {data['name']}\n# written by mechloop cam from the cam design; the "
              "profile is the envelope\n# 'profile' (branch -1), as in seed 000 sec. 2.4.\n")
    text = (json.dumps(data, indent=2) + "\n" if target.suffix.lower() == ".json"
            else header + yaml.safe_dump(data, sort_keys=False, allow_unicode=True))
    atomic_write_text(target, text)
    return target
