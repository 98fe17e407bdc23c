"""Gear meshes of the dynamic part of a model file (``gears:``): the higher pairs the
force analysis takes into account.

A mesh names its two bodies (the force is the one of the first on the second), the pitch
point ``at`` (a point on a vector, as everywhere: e.g. on the frame vector between the
two axes, or on a carrier arm) and the pressure angle (default 20°).  The gears' angles
are linked with the ratio in the vector model (``{link: ..., ratio: -z1/z2}``); the mesh
adds to the force analysis one unknown, the tangential force ``F_t`` at the pitch point,
with the normal force along the line of action (``|F_t|·tan α`` radial, separating the
gears) and no friction.  A gear of ``ring`` (internal teeth) is pushed outward.
"""

from __future__ import annotations

from pydantic import Field

from mechloop.model.dynamic import PointOn
from mechloop.model.signals import Scalar, _Frozen


class GearMesh(_Frozen):
    """A gear mesh between two bodies (a higher pair): one unknown, the tangential force
    at the pitch point; the radial force ``|F_t|·tan α`` pushes the gears apart."""

    bodies: tuple[int, int] = Field(description="the two gears' bodies; the force is the one "
                                    "of the first on the second")
    at: PointOn = Field(description="the pitch point, on a vector (e.g. the frame vector "
                        "between the axes or a carrier arm)")
    pressure_angle: Scalar = Field(20.0, description="pressure angle (angle units), "
                                   "0 to below 90")
    ring: int | None = Field(None, description="the body of the two with internal teeth "
                             "(a ring gear), if any")
