"""The summary of a simulation run in words (``mechloop simulate``, the web's simulation
job): the machine, the events, the cycles, the steady state and the energy balance, in
English or Russian (units in Russian, the decimal comma).

Each line is ``(text, warning)``: a warning is printed to the error stream.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from mechloop.dynamics.motors import RPM

WORDS: dict[str, dict[str, str]] = {
    "en": {
        "machine": "motor: {motor}; reduced inertia {low} … {high} kg*m^2 ({periodic}; "
                   "between positions within about {error} kg*m^2, slope within {slope} "
                   "kg*m^2/rad of dJ/dq)",
        "none": "none", "periodic": "periodic", "not periodic": "not periodic",
        "stretch": "{end}: the machine is the stretch of positions between the breaks, not "
                   "a cycle — no cycle, steady state or δ",
        "cycles": "{count} cycle(s); the last: mean speed {mean} rpm, {low} … {high} rpm "
                  "at the positions, δ = {delta}",
        "steady": "time to steady state {t} s (the first cycle whose mean speed changed by "
                  "less than {steady})",
        "unsteady": "not steady yet (the mean speed still changes by more than {steady} "
                    "from cycle to cycle)",
        "energy": "energy: motor {motor} J, loads {loads} J, kinetic energy {start} → {end} "
                  "J; balance residual at most {residual} J",
        "inputs": "{count} inputs (arguments {arguments}), Lagrange's equations solved at "
                  "every state ({solves} kinematic solves, {steps} steps); motors: {motors}",
        "input event": "{kind}{detail}: t = {t} s, angles {angles} deg, speeds {speeds} rpm",
        "inputs energy": "energy: motors {motor} J, loads {loads} J, kinetic energy {start} "
                         "→ {end} J; balance residual at most {residual} J",
    },
    "ru": {
        "machine": "двигатель: {motor}; приведённый момент инерции {low} … {high} кг·м² "
                   "({periodic}; между положениями с точностью около {error} кг·м², "
                   "производная dJ/dq с точностью {slope} кг·м²/рад)",
        "none": "нет", "periodic": "периодический", "not periodic": "непериодический",
        "stretch": "{end}: машина — участок положений между разрывами, а не цикл: цикла, "
                   "установившегося режима и δ нет",
        "cycles": "циклов: {count}; последний: средняя скорость {mean} об/мин, {low} … "
                  "{high} об/мин в положениях, δ = {delta}",
        "steady": "время выхода на установившийся режим {t} с (первый цикл, средняя "
                  "скорость которого изменилась меньше чем на {steady})",
        "unsteady": "режим ещё не установился (средняя скорость меняется от цикла к циклу "
                    "больше чем на {steady})",
        "energy": "энергия: работа двигателя {motor} Дж, работа нагрузок {loads} Дж, "
                  "кинетическая энергия {start} → {end} Дж; невязка баланса не больше "
                  "{residual} Дж",
        "inputs": "входов: {count} (аргументы {arguments}), уравнения Лагранжа решены в "
                  "каждом состоянии (кинематических расчётов: {solves}, шагов: {steps}); "
                  "двигатели: {motors}",
        "input event": "{kind}{detail}: t = {t} с, углы {angles}°, скорости {speeds} "
                       "об/мин",
        "inputs energy": "энергия: работа двигателей {motor} Дж, работа нагрузок {loads} "
                         "Дж, кинетическая энергия {start} → {end} Дж; невязка баланса не "
                         "больше {residual} Дж",
    },
}


def summary_lines(sim: Any, lang: str = "en") -> list[tuple[str, bool]]:
    """The summary of run ``sim`` (a :class:`~mechloop.dynamics.simulate.Simulation` or
    an :class:`~mechloop.dynamics.simulate_inputs.InputsSimulation`), line by line, in
    ``lang`` ('en' or 'ru'): ``(text, warning)``."""
    from mechloop.dynamics.simulate_inputs import InputsSimulation
    from mechloop.views.decimal_mark import localized

    lines = (_inputs_lines(sim, lang) if isinstance(sim, InputsSimulation)
             else _machine_lines(sim, lang))
    return [(localized(text, lang), warning) for text, warning in lines]


def _machine_lines(sim: Any, lang: str) -> list[tuple[str, bool]]:
    words = WORDS[lang]
    machine = sim.machine
    accuracy = machine.interpolation
    lines = [(words["machine"].format(
        motor=sim.motor.title(lang) if sim.motor else words["none"],
        low=f"{machine.inertia.min():.6g}", high=f"{machine.inertia.max():.6g}",
        periodic=words["periodic" if machine.periodic else "not periodic"],
        error=f"{accuracy.inertia_error:.2g}", slope=f"{accuracy.slope_error:.2g}"), False)]
    lines += [(event.describe(lang), False) for event in sim.events[1:]]
    lines += [(words["stretch"].format(end=end.describe(lang=lang)), True)
              for end in machine.breaks if end is not None]
    count = sim.cycle_time.size
    if count:
        _, _, omega = sim.cycle_profile()
        mean = sim.cycle_speed[-1]
        lines.append((words["cycles"].format(
            count=count, mean=f"{mean / RPM:.6g}", low=f"{omega.min() / RPM:.6g}",
            high=f"{omega.max() / RPM:.6g}",
            delta=f"{(omega.max() - omega.min()) / mean:.4g}"), False))
    if sim.steady_time is not None:
        lines.append((words["steady"].format(t=f"{sim.steady_time:.6g}",
                                             steady=f"{sim.settings.steady:g}"), False))
    elif count:
        lines.append((words["unsteady"].format(steady=f"{sim.settings.steady:g}"), False))
    lines.append((words["energy"].format(**_energy(sim)), False))
    return lines


def _inputs_lines(sim: Any, lang: str) -> list[tuple[str, bool]]:
    from mechloop.dynamics.simulate_words import RUSSIAN_KINDS

    words = WORDS[lang]
    joined = "; " if lang == "ru" else ", "  # the decimal comma is in the numbers
    motors = joined.join(f"{sim.machine.inputs[i]}: {m.title(lang)}" for i, m in
                         sorted(sim.motors.items())) or words["none"]
    lines = [words["inputs"].format(count=len(sim.inputs),
                                    arguments=", ".join(map(str, sim.inputs)),
                                    solves=sim.evaluations, steps=sim.steps, motors=motors)]
    for event in sim.events[1:]:
        kind = RUSSIAN_KINDS.get(event.kind, event.kind) if lang == "ru" else event.kind
        lines.append(words["input event"].format(
            kind=kind, detail=f" ({_detail(event.detail, lang)})" if event.detail else "",
            t=f"{event.t:.6g}", angles=joined.join(f"{math.degrees(v):.6g}" for v in event.q),
            speeds=joined.join(f"{v / RPM:.6g}" for v in event.omega)))
    lines.append(words["inputs energy"].format(**_energy(sim)))
    return [(line, False) for line in lines]


def _detail(detail: str, lang: str) -> str:
    """An event's detail ('contour 3', 'input 1') in ``lang``."""
    if lang != "ru":
        return detail
    word, _, rest = detail.partition(" ")
    return f"{ {'contour': 'контур', 'input': 'вход'}.get(word, word)} {rest}".strip()


def _energy(sim: Any) -> dict[str, str]:
    return {"motor": f"{sim.motor_work[-1]:.6g}", "loads": f"{sim.load_work[-1]:.6g}",
            "start": f"{sim.kinetic_energy[0]:.6g}", "end": f"{sim.kinetic_energy[-1]:.6g}",
            "residual": f"{np.abs(sim.balance).max():.2g}"}
