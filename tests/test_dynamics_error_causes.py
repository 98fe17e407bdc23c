"""The dynamics tell a failed machine motion or friction by the error's kind, not by its
message: each cause of :class:`~mechloop.dynamics.machine.MachineError` is told at the key
of the model to change, whatever the words of the message, and the cause survives
pickling (errors cross process boundaries in the CLI's workers)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from mechloop.dynamics import analysis
from mechloop.dynamics.cycle import steady_cycle
from mechloop.dynamics.kinetostatics import FrictionError
from mechloop.dynamics.machine import MachineError, machine_motion
from mechloop.dynamics.reduced import Reduced
from mechloop.errors import ModelSolveError, SolveError
from mechloop.model.dynamic import Machine

WHERE = {"cycle": ("machine",), "advance": ("arguments", 1), "stops": ("time",),
         "inertia": ("bodies",), "unsteady": ("machine",)}


@pytest.mark.parametrize("cause", sorted(WHERE))
def test_each_cause_is_told_at_its_key_whatever_the_message(cause):
    error = MachineError("some other wording", "a hint", cause=cause)
    told = analysis._machine_error(error, 1)
    assert isinstance(told, ModelSolveError)
    assert told.problems[0].path == WHERE[cause]
    assert told.problems[0].hint == analysis._MACHINE_FIXES[cause][1]


def test_an_error_of_no_known_cause_is_told_at_machine():
    told = analysis._machine_error(SolveError("the machine stops: a plain error"), 1)
    assert told.problems[0].path == ("machine",)
    assert "check the loads" in told.problems[0].hint


def test_the_cause_survives_pickling_and_errors_stay_solve_errors():
    error = pickle.loads(pickle.dumps(MachineError("m", "h", cause="stops")))
    assert (error.message, error.hint, error.cause) == ("m", "h", "stops")
    assert issubclass(MachineError, SolveError) and issubclass(FrictionError, SolveError)


def test_the_machine_raises_its_causes():
    q = np.linspace(0.0, 2 * np.pi, 37)
    time = q / 10.0
    flat = np.zeros_like(q)
    spec = Machine()
    with pytest.raises(MachineError) as broken:  # a NaN in the cycle: the chain breaks
        steady_cycle(q, time, Reduced(np.where(q > 3, np.nan, 1.0), flat, flat), flat,
                     np.ones_like(q), spec)
    assert broken.value.cause == "cycle"
    with pytest.raises(MachineError) as back:  # the input goes back
        steady_cycle(q[::-1], time, Reduced(np.ones_like(q), flat, flat), flat,
                     np.ones_like(q), spec)
    assert back.value.cause == "advance"
    with pytest.raises(MachineError) as empty:  # no inertia at one position
        machine_motion(q, np.where(q > 3, 0.0, 1.0), flat, omega_mean=10.0)
    assert empty.value.cause == "inertia"
    with pytest.raises(MachineError) as stops:  # a load swing far above the energy
        machine_motion(q, np.full_like(q, 1e-6), 1e3 * np.sin(q), omega_mean=1.0)
    assert stops.value.cause == "stops"
    with pytest.raises(MachineError) as unsteady:  # net work left over the cycle
        machine_motion(q, np.ones_like(q), np.ones_like(q), omega_mean=10.0)
    assert unsteady.value.cause == "unsteady"
