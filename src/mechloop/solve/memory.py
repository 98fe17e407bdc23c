"""Whether a solve fits in the machine's memory, checked before any array is allocated.

The kinematic solve keeps, per position, three float64 arrays per varying parameter and
their table (measured: about 56 bytes per position per vector, e.g. 224 B for a
four-vector slider-crank); the dynamics add the complex motions of points, masses, loads
and reactions (measured: about 3 kB per position for the slider-crank with three bodies,
four joints and a force).  :func:`estimate_bytes` is a bound fitted to those measurements
(with room to spare); :func:`require_memory` refuses a model whose estimate exceeds the
memory the machine has available, naming ``positions`` and the most it can take.
"""

from __future__ import annotations

import os

from mechloop.errors import ModelSolveError, Problem

#: Bytes per position per vector and per contour (kinematics with its table).
PER_VECTOR = 64
#: Bytes per position per body, joint and load (the dynamics).
PER_DYNAMIC_ITEM = 400
#: Share of the available memory a solve may plan to use.
USABLE_SHARE = 0.8


def available_memory() -> int | None:
    """Bytes of memory available to a new allocation (Linux ``MemAvailable``, else the
    free physical pages), or None when the system does not say."""
    try:
        with open("/proc/meminfo") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):
        return None


def bytes_per_position(model, *, dynamics: bool) -> int:
    """Estimated bytes a solve of ``model`` holds per calculation position."""
    size = PER_VECTOR * (len(model.vectors) + len(model.contours))
    if dynamics:
        items = (len(model.bodies) + len(model.joints or {}) + len(model.forces)
                 + len(model.moments) + len(model.bodies))  # pairs are about one per body
        size += PER_DYNAMIC_ITEM * items
    return size


def estimate_bytes(model, *, dynamics: bool, designs: int = 1) -> int:
    """Estimated peak bytes of solving ``designs`` designs of ``model`` (its kinematics,
    and with ``dynamics`` its force analysis) over positions 0..N."""
    return designs * (model.positions + 1) * bytes_per_position(model, dynamics=dynamics)


def require_memory(model, *, dynamics: bool = False, designs: int = 1,
                   available: int | None = None) -> None:
    """Raise a :class:`~mechloop.errors.ModelSolveError` at ``positions`` when solving
    ``designs`` designs of ``model`` would need more memory than the machine has
    available (``available`` bytes; read from the system when None)."""
    available = available_memory() if available is None else available
    if available is None:
        return
    need = estimate_bytes(model, dynamics=dynamics, designs=designs)
    budget = USABLE_SHARE * available
    if need <= budget:
        return
    per_design = bytes_per_position(model, dynamics=dynamics) * max(designs, 1)
    most = max(int(budget // per_design) - 1, 1)
    what = f"{model.positions + 1:,} positions" + (f" of {designs:,} designs"
                                                   if designs > 1 else "")
    raise ModelSolveError([Problem(
        ("positions",), f"solving {what} needs about {_gib(need)} of memory; this "
        f"machine has {_gib(available)} available",
        f"use fewer positions (at most about {most:,} here)"
        + (" or fewer designs" if designs > 1 else ""))])


def _gib(size: float) -> str:
    return f"{size / 2**30:.3g} GiB"
