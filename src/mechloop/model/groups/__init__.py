"""Mechanisms built from Assur groups: an input group L0 and a sequence of class-II dyads
(seed 002: L1 RRR, L2 RRP, L3 RPR, L4 PRP, L5 RPP) and class-III triads (``III``: a
ternary middle link on three legs, :mod:`.triads`), turned into the ordinary vector model.

The package, one step per module (imports flow down this list, never back):

* :mod:`.files` — reading a group file (validated, every problem located), the mechanism
  a file describes, dimensions set and the file written back;
* :mod:`.build` — :func:`build`, :func:`build_model` and what a built model says;
* :mod:`.builder` — the builder: the input, each group in file order, the loose ends, the
  checked vector model;
* :mod:`.inputs`, :mod:`.dyads`, :mod:`.triads` — one step per group kind;
  :mod:`.bodies` — bodies, joints, masses and loads; :mod:`.dimensions` — point
  locations, dimension carriers, the synthesis task;
* :mod:`.places` — guides and points fixed in links; :mod:`.names` — point and link
  names declared and resolved;
* :mod:`.core` — the builder's state and elementary steps (numbers, segments, contours);
* :mod:`.located` — :class:`Carrier`, :class:`PointLocation`, :class:`BuiltModel`;
* :mod:`.spec` — the file's schema (pydantic classes).

A :class:`GroupMechanism` names its **points** and **links** and states dimensions; the
builder (:func:`build_model`, :func:`build`) writes the vectors, the contours with their
modules (Pl1–Pl4) and ``start`` placements, the bodies and the joints.  A model file whose
top level has ``groups:`` (and no ``vectors:``) is such a mechanism;
:func:`mechloop.load_model` returns the generated :class:`~mechloop.model.schema.Model`.

**Points.**  Every point has a unique name (no dots): the ``ground`` points, the input's
``joint``, each group's ``joint`` (``point`` for L5; a triad's legs' ``joint``) and the
``points`` placed on links.  A
reference to a point is ``NAME`` or ``LINK.NAME``.  A bare name means the point on the link
that introduced it — a ground point on the ground, the input's joint on the input link, a
point of ``points`` on its link.  The internal joint of L1, L2 and L4 belongs to both links
of its group (a triad's joints: the leg and the middle link), so name the link:
``coupler.B`` or ``rocker.B``.  A group may use only
points of the ground, the input and earlier groups.

**Lines of links.**  Angles of points on a link are measured from the link's *line*,
counter-clockwise, and ``{share: s}`` goes along it from its first to its second point:

==========================  =====================================================  =========
link                        line (first point → direction)                         2nd point
==========================  =====================================================  =========
ground                      +X                                                     —
crank (input)               pivot → joint                                          joint
slider (input, L2, L4)      its joint, along its guide's direction                 —
L1 first / second link      attachment → joint (both: pivot to pin)                joint
L2 rod                      attachment → joint                                     joint
L3 block and guide          the guide's pivot → the block's pin (block: its pin)   —
L5 block / yoke             pin, along the slot / ``point``, along the guide        —
triad pinned leg            attachment → joint                                     joint
triad sliding leg           its joint, along its guide's direction                 —
triad middle link           first leg's joint → second leg's joint                 J2
==========================  =====================================================  =========

**Assembly variants** (``variant: 1 | 2 | auto``): L1 — 1 puts the joint on the left of
the line from the first attachment to the second; L2 — 1 puts the joint ahead of the
attachment along the guide direction (2: behind).  L3 (whose slide passes through the
guide's pivot), L4 and L5 have one assembly.  A triad has up to six: its ``guess``
(approximate positions at position 0 of its joints and moving attachments) picks one, as
the start of Newton's method on its coupled block.

**A guide** is the line through a placed point ``through`` at ``angle`` from the line of
that point's link (from +X on the ground), shifted ``offset`` to its left; the guide belongs
to the link of ``through``.  An L3 slide has no offset: with one, the slide's direction and
offset turn together and no elementary module solves the loop.

**The vector model.**  Each group is one contour that runs from a ground point along the
vectors that reach its first attachment, through its own vectors, back along the vectors of
its second attachment and through the ground.  Vectors of links are written once and copied
(``{link: rK}``, ``{link: aK, delta: 180}``) where another contour passes them; ground points
are reached from the first ground point (the *root*) by one frame vector each.  A point on
a link that no group uses is placed by a Pl1 contour of its own (``P → X`` closing to the
point it is measured from).  Bodies are numbered as the structure formula numbers the links
(the input 1, then two per group), joints are written explicitly: pins named after their
point (``O``, ``A``; a second pin at the same point ``O2``), slides ``S`` + the pin of the
sliding link (``SB``).

:func:`build` also says where each named point is (:class:`PointLocation`) and which vector
parameter carries each dimension (:class:`Carrier`).

**Synthesis** (``synthesis:``, :class:`GroupSynthesisTask`) varies dimensions by the names
:func:`dimension_names` lists — paths in the document (``input.length``,
``groups[0].lengths[1]``, ``points.P.angle``) and ``ground.C.x`` / ``ground.C.y`` — and
traces named points.  The builder writes the vector model's task with one
:class:`~mechloop.model.synthesis.Dimension` per varied name: the constants it sets (its
carriers; for a ground coordinate the components of the frame vectors it ends and the
starts of the contours that start there, written as coordinates even at the origin).
:func:`with_dimensions` puts a result's values back into the mechanism,
:func:`save_mechanism` writes it, :func:`mechanism_of` reads a group file.
"""

from mechloop.model.groups.build import (
    build,
    build_model,
    dimension_names,
    dimension_parameters,
    point_vectors,
)
from mechloop.model.groups.core import _tidy
from mechloop.model.groups.files import (
    mechanism_of,
    mechanism_text,
    model_from_group_data,
    save_mechanism,
    with_dimensions,
)
from mechloop.model.groups.located import BuiltModel, Carrier, PointLocation
from mechloop.model.groups.spec import (
    GROUND,
    KIND,
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    CrankInput,
    Group,
    GroupMechanism,
    GroupMotionTask,
    GroupPathTask,
    GroupSynthesisTask,
    GroupWorkspace,
    Guide,
    Input,
    LinkForce,
    LinkMass,
    LinkMoment,
    LinkPoint,
    Share,
    SliderInput,
    group_json_schema,
)

__all__ = [
    "GROUND", "KIND", "PRP", "RPP", "RPR", "RRP", "RRR", "BuiltModel", "Carrier",
    "CrankInput", "Group", "GroupMechanism", "GroupMotionTask", "GroupPathTask",
    "GroupSynthesisTask", "GroupWorkspace", "Guide", "Input", "LinkForce", "LinkMass",
    "LinkMoment", "LinkPoint", "PointLocation", "Share", "SliderInput", "_tidy", "build",
    "build_model", "dimension_names", "dimension_parameters", "group_json_schema",
    "mechanism_of", "mechanism_text", "model_from_group_data", "point_vectors",
    "save_mechanism", "with_dimensions",
]
