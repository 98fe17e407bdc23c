"""Spatial vector models (issue 17, first part): the spatial vector and the elementary
spatial modules Pr1–Pr20 of seed 000 table 2.1 as pure array functions.

A spatial contour closes when ``Σ r_i (cos α_i cos β_i, sin α_i, cos α_i sin β_i) = 0``
(seed 000 eq. 1.1): ``α`` is the elevation above the XZ plane, ``β`` the rotation about
Y (:mod:`.vector`, with the two parameter-range conventions of sec. 1.1).  Every module
function takes ``S = (sx, sy, sz)``, the sum of the contour's known vectors, and the known
parameters of the vectors ``i, j, k`` that carry the three unknowns, all broadcasting
over ``(..., P)`` (positions last, designs leading).  It returns the three unknowns and
``ok``, each of shape ``(B, ..., P)`` — **every solution branch** on a leading axis
(``B`` = the table's count); a branch with no real solution at a position (a chain
break) is NaN there with ``ok`` false, never a warning or an exception.  Unknown lengths
are signed, except that a length found together with its own vector's elevation is
``≥ 0`` (as Pl1); an unknown angle is a full turn ``(−π, π]``, except that both angles of
one vector are returned in the chosen ``convention``.

======  ============  ========  ======  =========================================  ==============
module  unknowns      branches  done    method                                     module file
======  ============  ========  ======  =========================================  ==============
Pr1     r_i α_i β_i   1         yes     inverse of the vector                      one_vector
Pr2     r_i α_i r_j   1         yes     normal of i's plane: linear                vertical_plane
Pr3     r_i α_i α_j   2         yes     normal of i's plane: cos α_j = c           vertical_plane
Pr4     r_i α_i β_j   2         yes     normal of i's plane: sin(β_j − β_i) = c    vertical_plane
Pr5     r_i β_i r_j   2         yes     cone ∩ line: quadratic                     cone
Pr6     r_i β_i α_j   4         yes     cone ∩ circle: trig. quartic (eigvals)     cone
Pr7     r_i β_i β_j   2         yes     cone ∩ horizontal circle                   cone
Pr8     α_i β_i r_j   2         yes     sphere ∩ line: quadratic                   sphere
Pr9     α_i β_i α_j   2         yes     sphere ∩ circle                            sphere
Pr10    α_i β_i β_j   2         yes     sphere ∩ horizontal circle                 sphere
Pr11    r_i r_j r_k   1         yes     linear 3×3 (Cramer)                        lengths
Pr12    r_i r_j α_k   2         yes     normal of (u_i, u_j): a cos + b sin = c    lengths
Pr13    r_i r_j β_k   2         yes     normal of (u_i, u_j): a cos + b sin = c    lengths
Pr14    r_i α_j α_k   4         yes     two ellipses: trig. quartic (eigvals)      ellipses
Pr15    r_i α_j β_k   4         yes     two ellipses: trig. quartic (eigvals)      ellipses
Pr16    α_i α_j α_k   8         yes     trig. octic (eigvals) + 3-D Newton         octic
Pr17    α_i α_j β_k   8         yes     trig. octic (eigvals) + 3-D Newton         octic
Pr18    β_i β_j r_k   2         yes     Y row linear, then Pl4 in XZ               horizontal
Pr19    β_i β_j α_k   4         yes     Y row sin α_k = c, then Pl4 in XZ          horizontal
Pr20    β_i β_j β_k   ∞         exist.  whether the family exists (indeterminate)  horizontal
======  ============  ========  ======  =========================================  ==============

Exact velocities and accelerations of the unknowns by the 3×3 Jacobian: :mod:`.rates`.

Models with spatial contours: :mod:`.contour` names a contour's module from its three
unknowns and follows a branch over the positions (a fixed variant, or continuity);
:mod:`.solve` solves a whole model, spatial and planar contours (any plane) together
(the model side: :mod:`mechloop.model.spatial`, :mod:`mechloop.model.plane`).  Not yet
here: coupled spatial blocks, many designs at once, views.  Dynamics: :mod:`.bodies`,
:mod:`.loads`, :mod:`.dynamics` (virtual power), :mod:`.joints` and :mod:`.reactions`
(the joints' reactions by the Newton–Euler equations, :mod:`.determinacy`);
:mod:`.directions` reads a given direction or axis.  What the planar and the spatial
mechanism share lives in :mod:`mechloop.dynamics` (:mod:`~mechloop.dynamics.placing`,
:mod:`~mechloop.dynamics.holds`, :mod:`~mechloop.dynamics.mass_items`), and a coupled
block is solved by the planar kernel (:mod:`mechloop.modules.coupled`).

Shared helpers: :mod:`.roots` (``a cos θ + b sin θ = c``, quadratics), :mod:`.quartic`
(real roots of a trigonometric polynomial of any degree by batched companion
eigenvalues), :mod:`.parts` (the rest of the unknowns once a root is known).
Verified in ``tests/test_spatial_modules.py`` (closure of every branch, the known
configuration found, a SciPy multi-start oracle for missed roots, the planar modules for
``β = 0``, finite differences for :mod:`.rates`).

The modules above import only NumPy and know nothing of models or files; :mod:`.solve`
reads models.
"""

from mechloop.spatial.cone import solve_pr5, solve_pr6, solve_pr7
from mechloop.spatial.ellipses import ellipse_pair, solve_pr14, solve_pr15
from mechloop.spatial.horizontal import horizontal_pair, pr20_family, solve_pr18, solve_pr19
from mechloop.spatial.lengths import solve_pr11, solve_pr12, solve_pr13
from mechloop.spatial.octic import solve_pr16, solve_pr17
from mechloop.spatial.one_vector import solve_pr1
from mechloop.spatial.rates import accelerations, rates
from mechloop.spatial.sphere import solve_pr8, solve_pr9, solve_pr10
from mechloop.spatial.vector import components, in_convention, parameters, unit
from mechloop.spatial.vertical_plane import solve_pr2, solve_pr3, solve_pr4

__all__ = [
    "accelerations",
    "components",
    "ellipse_pair",
    "horizontal_pair",
    "in_convention",
    "parameters",
    "pr20_family",
    "rates",
    "solve_pr1",
    "solve_pr2",
    "solve_pr3",
    "solve_pr4",
    "solve_pr5",
    "solve_pr6",
    "solve_pr7",
    "solve_pr8",
    "solve_pr9",
    "solve_pr10",
    "solve_pr11",
    "solve_pr12",
    "solve_pr13",
    "solve_pr14",
    "solve_pr15",
    "solve_pr16",
    "solve_pr17",
    "solve_pr18",
    "solve_pr19",
    "unit",
]
