"""Views: position plans, animations, plots of parameters and dynamics, the report.

Everything here reads solved results (:class:`~mechloop.solve.results.Results`,
:class:`~mechloop.dynamics.analysis.DynamicResults`) and draws with matplotlib; it never
solves or changes a model.  Functions return a ``matplotlib.figure.Figure`` (or write a
file); :func:`mechloop.views.figure.save_figure` writes PNG, SVG or PDF atomically.
"""
