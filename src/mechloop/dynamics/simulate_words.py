"""The words of a simulation's events (:meth:`mechloop.dynamics.simulate.Event.describe`)
in each language: English, and Russian (units in Russian, the decimal comma)."""

from __future__ import annotations

WORDS: dict[str, dict[str, str]] = {
    "en": {
        "event": "{kind}: t = {t} s, angle {q} deg, speed {omega} rpm",
        "break": " — the run stops at the last position before the break; the chain "
                 "breaks at angle {at} deg, {further} deg further on",
        "range": " — the input reached the end of the model's range (the positions are "
                 "a range, not whole turns): nothing is known beyond it",
    },
    "ru": {
        "event": "{kind}: t = {t} с, угол {q}°, скорость {omega} об/мин",
        "break": " — движение остановлено в последнем положении перед разрывом; цепь "
                 "разрывается при угле {at}°, на {further}° дальше",
        "range": " — вход достиг конца диапазона модели (положения — диапазон, а не целые "
                 "обороты): за ним ничего не известно",
    },
}

#: The kinds of events (:class:`~mechloop.dynamics.simulate.Event`) in Russian.
RUSSIAN_KINDS: dict[str, str] = {
    "start": "пуск", "motor off": "двигатель отключён", "stopped": "остановка",
    "range": "конец диапазона", "chain break ahead": "впереди разрыв цепи",
    "angle": "заданный угол", "steady": "установившийся режим", "cycles": "число циклов",
    "duration": "время моделирования",
}
