"""Force analysis from Python: reactions, balancing moment, reduced characteristics, energy.

Run from the repository root:  python examples/dynamics_api.py
"""

from pathlib import Path

import numpy as np

import mechloop

HERE = Path(__file__).parent

model = mechloop.load_model(HERE / "crank_slider_dynamics.yaml")
dyn = mechloop.solve_dynamics(model)

# balancing moment on the crank: by kinetostatics and, independently, by virtual power
m_bal = dyn.forces.balancing[1]  # N*m, one value per position
print(f"peak balancing moment {np.abs(m_bal).max():.2f} N*m; the two methods differ by "
      f"{np.abs(m_bal - dyn.balancing_vp[1]).max():.1e} N*m")

# reactions: the force of the first body of each joint on the second (complex Fx + i*Fy)
for name, reaction in dyn.forces.reactions.items():
    print(f"joint {name} ({reaction.pair.kind}, bodies {reaction.pair.bodies}): "
          f"peak |R| = {np.abs(reaction.force).max():.1f} N")

# reduced moment of inertia to the crank and its derivative with respect to the crank angle
print(f"J_red from {dyn.reduced.inertia.min():.5f} to {dyn.reduced.inertia.max():.5f} kg*m^2")

# the whole table (kinematic and dynamic columns) and the summary of work and power
frame = dyn.to_frame()
print(frame[["position", "M_bal [N*m]", "J_red [kg*m^2]", "RA [N]", "RS_n [N]"]].head())
print(dyn.summary.to_frame())

# friction: the same mechanism with f = 0.1 in every pair
rough = mechloop.solve_dynamics(mechloop.load_model(HERE / "crank_slider_friction.yaml"))
print(f"friction takes {rough.summary.friction_work:.1f} J per revolution; "
      f"peak balancing moment {np.abs(rough.forces.balancing[1]).max():.2f} N*m")
