"""The dynamic table (``DynamicResults.to_frame``) shows the solved arrays, and for every
joint the angle of its reaction to each vector that ends at the joint (the docstring's
promise), computed here from the reaction and the vector angle.

The bundled slider-crank: pin O joins the crank (vector 1, its tail) and the ground (the
offset vector 4 ends there); pin A the crank (head of 1) and the rod (tail of 2); pin B
the rod (head of 2) and the slider (tail of 3); the slide S sits at the tail of 3.
"""

from __future__ import annotations

import numpy as np
import pytest
from oracles.dynamic_models import dynamics, example

VECTORS_AT = {"O": (1, 4), "A": (1, 2), "B": (2, 3), "S": (3,)}


@pytest.fixture(scope="module")
def solved():
    d = dynamics(example("crank_slider_dynamics.yaml"))
    return d, d.to_frame()


def test_table_holds_the_solved_arrays(solved):
    d, frame = solved
    np.testing.assert_array_equal(frame["M_bal [N*m]"], d.forces.balancing[1])
    np.testing.assert_array_equal(frame["M_bal_vp [N*m]"], d.balancing_vp[1])
    np.testing.assert_array_equal(frame["J_red [kg*m^2]"], d.reduced.inertia)
    np.testing.assert_array_equal(frame["dJ_red [kg*m^2/rad]"], d.reduced.d_inertia)
    np.testing.assert_array_equal(frame["M_red [N*m]"], d.reduced.load)
    np.testing.assert_array_equal(frame["T [J]"], d.kinetic_energy)
    for name, r in d.forces.reactions.items():
        np.testing.assert_array_equal(frame[f"R{name}_x [N]"], r.force.real)
        np.testing.assert_array_equal(frame[f"R{name}_y [N]"], r.force.imag)
        np.testing.assert_array_equal(frame[f"R{name} [N]"], np.abs(r.force))
    np.testing.assert_array_equal(frame["RS_n [N]"], d.forces.reactions["S"].normal)
    np.testing.assert_array_equal(frame["RS_m [N*m]"], d.forces.reactions["S"].moment)
    for body, motion in d.centers.items():
        np.testing.assert_array_equal(frame[f"xS{body} [m]"], motion.z.real)
    assert list(frame.columns)[-1] == "chain_break"


def test_table_gives_reaction_angles_to_the_vectors_at_each_joint(solved):
    d, frame = solved
    for name, vectors in VECTORS_AT.items():
        force = d.forces.reactions[name].force
        for v in vectors:
            column = f"R{name}_to_a{v} [deg]"
            assert column in frame.columns, column
            want = np.degrees(np.angle(force * np.exp(-1j * d.kinematics.value(f"a{v}"))))
            np.testing.assert_allclose(frame[column], want, rtol=0, atol=1e-9)
