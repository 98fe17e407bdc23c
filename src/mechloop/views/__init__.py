"""Views: position plans, animations, plots of parameters and dynamics, the report.

Everything here reads solved results (:class:`~mechloop.solve.results.Results`,
:class:`~mechloop.dynamics.analysis.DynamicResults`) and draws with matplotlib; it never
solves or changes a model.  Functions return a ``matplotlib.figure.Figure`` (or write a
file); :func:`mechloop.views.figure.save_figure` writes PNG, SVG or PDF atomically.

* ``figure`` — figures without pyplot state, atomic saving;
* ``display`` — display units and precision (KDAM's "units" and "tolerances" panels);
* ``plan``, ``animation`` — position plans, overlays, trajectories, animations;
* ``scene`` — what the planar and the 3-D scenes share (positions, vector colours);
* ``curves`` — parameters, combinations, angle differences, increments;
* ``dynamics`` — reduced characteristics, balancing loads, reactions, hodographs,
  the summary table, machine motion;
* ``spatial_reactions`` — the joint reactions of a spatial model: magnitudes over the
  positions, the force (moment) hodograph in 3-D with its projections;
* ``motion`` — the motion in time (:class:`~mechloop.dynamics.simulate.Simulation`):
  angle, speed, acceleration over time and the phase portrait;
* ``formula`` — the structure and parametric formulas drawn;
* ``russian`` — the figures' words in Russian: ``translate(figure, "ru")`` after drawing,
  the user's names (marked by the views with ``keep_names``) kept as written;
* ``report`` — the course-project report (PDF, English and Russian).

May import the model, the solver and the dynamics; nothing imports the views but the CLI.
"""
