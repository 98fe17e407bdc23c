"""The parameters of an ideal working cycle: an engine's (two- or four-stroke) and a piston
compressor's.  SI: pressures in Pa, ratios and exponents dimensionless.

**Engine** (the calculated indicator diagram of engine theory): compression ratio
``ε = (V_c + V_h)/V_c``; the charge at ``p_a`` (``intake``) is compressed along the
polytrope ``n₁`` to ``p_c = p_a·ε^n₁`` (four-stroke; a two-stroke compresses from where
the piston closes its exhaust port); combustion raises the pressure at constant volume to
``p_z = λ·p_c`` (``pressure_ratio`` λ) and then, at constant pressure, expands the gas to
``V_z = ρ·V_c`` (``pre_expansion`` ρ; ρ = 1: combustion at constant volume, λ = 1: at
constant pressure, both: the mixed Trinkler–Sabathé cycle); expansion along ``n₂`` to
bottom dead centre (four-stroke) or to the exhaust port (two-stroke).  A four-stroke
exhausts at ``exhaust`` (``p_r``) and draws in at ``p_a``; a two-stroke's exhaust port
(``exhaust_port``: the share of the stroke it takes above bottom dead centre) opens and the
pressure falls at once to the scavenging pressure ``p_a`` until the piston covers the
port again.

**Compressor** (the real cycle with a clearance): the gas left in the clearance
``V_c = c·V_h`` (``clearance`` c) re-expands along ``n_e`` from ``p_d`` (``discharge``)
to ``p_s`` (``suction``); suction at ``p_s`` to bottom dead centre; compression along
``n_c`` to ``p_d``; discharge at ``p_d`` to top dead centre.  Valves open at once, without
pressure losses.
"""

from __future__ import annotations

from dataclasses import dataclass

from mechloop.errors import HintedError


def _positive(**values: float) -> None:
    for name, value in values.items():
        if not value > 0:
            raise HintedError(f"{name} must be positive, got {value!r}",
                              f"give a positive {name}")


@dataclass(frozen=True)
class EngineCycle:
    """An engine's cycle.

    Attributes
    ----------
    strokes : 2 or 4.
    compression_ratio : ε > 1 (geometric: over the whole stroke).
    pressure_ratio : λ = p_z/p_c ≥ 1.
    pre_expansion : ρ = V_z/V_c, 1 ≤ ρ (< ε, and the gas must reach V_z before the
        exhaust port opens).
    compression_exponent, expansion_exponent : n₁, n₂ > 1.
    intake : p_a, Pa — the intake line (four-stroke) or the scavenging pressure
        (two-stroke), and the start of compression.
    exhaust : p_r, Pa — the exhaust line of a four-stroke (None for a two-stroke).
    exhaust_port : share of the stroke above bottom dead centre that the exhaust port takes,
        0 ≤ ψ < 1 (two-stroke; 0 for a four-stroke).
    """

    strokes: int
    compression_ratio: float
    pressure_ratio: float
    pre_expansion: float
    compression_exponent: float
    expansion_exponent: float
    intake: float
    exhaust: float | None = None
    exhaust_port: float = 0.0

    def __post_init__(self) -> None:
        if self.strokes not in (2, 4):
            raise HintedError(f"an engine has 2 or 4 strokes, got {self.strokes!r}",
                              "give strokes: 2 or strokes: 4")
        _positive(intake=self.intake)
        if not self.compression_ratio > 1:
            raise HintedError(f"the compression ratio must exceed 1, got "
                              f"{self.compression_ratio!r}", "typical: 8 to 11 (spark "
                              "ignition), 14 to 22 (diesel)")
        if not self.pressure_ratio >= 1 or not self.pre_expansion >= 1:
            raise HintedError("the pressure ratio λ and the pre-expansion ρ are at least 1",
                              "λ = 1 is combustion at constant pressure, ρ = 1 at "
                              "constant volume")
        for name in ("compression_exponent", "expansion_exponent"):
            if not getattr(self, name) > 1:
                raise HintedError(f"the {name.replace('_', ' ')} must exceed 1, got "
                                  f"{getattr(self, name)!r}", "typical: 1.3 to 1.4 "
                                  "(compression), 1.2 to 1.3 (expansion)")
        if self.strokes == 4:
            if self.exhaust is None:
                raise HintedError("a four-stroke cycle needs its exhaust pressure",
                                  "give exhaust: (e.g. 0.11 MPa)")
            _positive(exhaust=self.exhaust)
            if self.exhaust_port:
                raise HintedError("a four-stroke engine has no exhaust port share",
                                  "leave out exhaust_port (it is for strokes: 2)")
        else:
            if self.exhaust is not None:
                raise HintedError("a two-stroke engine exhausts through its port into the "
                                  "scavenging pressure: it has no exhaust line",
                                  "leave out exhaust; give exhaust_port")
            if not 0 <= self.exhaust_port < 1:
                raise HintedError(f"the exhaust port's share of the stroke is in [0, 1), "
                                  f"got {self.exhaust_port!r}", "typical: 0.1 to 0.3")
        if not self.pre_expansion * 1.0 <= self.port_ratio:
            raise HintedError(f"the pre-expansion ρ = {self.pre_expansion:g} ends beyond "
                              "where expansion ends", f"keep ρ ≤ {self.port_ratio:.6g} "
                              "(V at the end of expansion over V_c)")

    @property
    def port_ratio(self) -> float:
        """``V_e/V_c``: the volume where expansion ends and (two-stroke) compression starts,
        over the clearance volume (ε for a four-stroke)."""
        eps = self.compression_ratio
        return 1.0 + (eps - 1.0) * (1.0 - self.exhaust_port)


@dataclass(frozen=True)
class CompressorCycle:
    """A single-acting piston compressor's cycle.

    Attributes
    ----------
    suction, discharge : p_s < p_d, Pa.
    clearance : c = V_c/V_h > 0.
    compression_exponent, expansion_exponent : n_c, n_e > 1 (compression, re-expansion
        of the clearance gas).
    """

    suction: float
    discharge: float
    clearance: float
    compression_exponent: float
    expansion_exponent: float

    def __post_init__(self) -> None:
        _positive(suction=self.suction, clearance=self.clearance)
        if not self.discharge > self.suction:
            raise HintedError("the discharge pressure must exceed the suction pressure",
                              "give discharge > suction")
        for name in ("compression_exponent", "expansion_exponent"):
            if not getattr(self, name) > 1:
                raise HintedError(f"the {name.replace('_', ' ')} must exceed 1, got "
                                  f"{getattr(self, name)!r}", "typical: 1.2 to 1.4")
        if not self.clearance * (self.pressure_ratio ** (1 / self.expansion_exponent) - 1) < 1:
            raise HintedError("the clearance gas re-expands over the whole stroke: the "
                              "compressor delivers nothing", "lower clearance or discharge "
                              "(volumetric efficiency 1 − c·(π^(1/n_e) − 1) must be > 0)")

    @property
    def pressure_ratio(self) -> float:
        """π = p_d/p_s."""
        return self.discharge / self.suction
