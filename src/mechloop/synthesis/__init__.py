"""Synthesis: objectives, constraints, search strategies, parametric sweeps, classical closed-form starting points."""  # noqa: E501
