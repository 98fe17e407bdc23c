"""The tables a gear task prints and writes: the pair's geometry gear by gear, and the
designs of a planetary choice (pandas DataFrames; lengths in mm, angles in degrees)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from mechloop.gears.pair import GearPair
from mechloop.gears.planetary import PlanetaryTrain, output_member
from mechloop.gears.tooth_search import Choice, WolfromChoice
from mechloop.gears.wolfrom import WolfromTrain


def pair_table(pair: GearPair) -> pd.DataFrame:
    """One row per quantity: ``quantity, symbol, pinion, wheel, unit`` (a value of the pair
    as a whole sits in the pinion's column, the wheel's left empty)."""
    chord, chord_height = pair.chordal
    per_gear = [
        ("number of teeth", "z", pair.zs, ""),
        ("profile shift coefficient", "x", pair.xs, ""),
        ("least shift without undercut", "x_min", pair.x_min, ""),
        ("reference diameter", "d", pair.d, "mm"),
        ("base diameter", "d_b", pair.d_b, "mm"),
        ("working pitch diameter", "d_w", pair.d_w, "mm"),
        ("tip diameter", "d_a", pair.d_a, "mm"),
        ("root diameter", "d_f", pair.d_f, "mm"),
        ("form diameter (involute starts)", "d_Ff", pair.d_Ff, "mm"),
        ("lowest contact diameter", "d_Nf", pair.d_Nf, "mm"),
        ("addendum", "h_a", pair.h_a, "mm"),
        ("dedendum", "h_f", pair.h_f, "mm"),
        ("tooth depth", "h", pair.h, "mm"),
        ("tooth thickness, reference circle", "s", pair.s, "mm"),
        ("space width, reference circle", "e", pair.e, "mm"),
        ("tooth thickness, working pitch circle", "s_w", pair.s_w, "mm"),
        ("tooth thickness, base circle", "s_b", pair.s_b, "mm"),
        ("tooth thickness, tip circle", "s_a", pair.s_a, "mm"),
        ("chordal thickness, reference circle", "s̄", chord, "mm"),
        ("chordal height, reference circle", "h̄", chord_height, "mm"),
        ("teeth in the span", "k", pair.k_span, ""),
        ("base tangent length (span)", "W_k", pair.W_k, "mm"),
        ("tip clearance", "c", pair.tip_clearances, "mm"),
    ]
    g_a, g_e = pair.active_line
    whole = [
        ("module", "m_n", pair.m_n, "mm"),
        ("pressure angle", "α_n", np.degrees(pair.alpha_n), "deg"),
        ("gear ratio", "u", pair.u, ""),
        ("reference centre distance", "a_0", pair.a0, "mm"),
        ("centre distance", "a", pair.a, "mm"),
        ("working pressure angle", "α_w", np.degrees(pair.alpha_w), "deg"),
        ("centre distance modification coefficient", "y", pair.y, ""),
        ("tip shortening coefficient", "Δy", pair.dy, ""),
        ("pitch", "p", pair.p, "mm"),
        ("base pitch", "p_b", pair.p_b, "mm"),
        ("line of action N1N2", "N1N2", pair.line_of_action, "mm"),
        ("start of contact from N1", "N1A", g_a, "mm"),
        ("end of contact from N1", "N1E", g_e, "mm"),
        ("length of path of contact", "g_α", pair.g_alpha, "mm"),
        ("transverse contact ratio", "ε_α", pair.eps_alpha, ""),
    ]
    rows = [(q, s, float(v[0]), float(v[1]), u) for q, s, v, u in per_gear]
    rows += [(q, s, float(v), np.nan, u) for q, s, v, u in whole]
    return pd.DataFrame(rows, columns=["quantity", "symbol", "pinion", "wheel", "unit"])


def thickness_table(pair: GearPair, diameters: list[float]) -> pd.DataFrame:
    """Tooth thickness on the circles ``diameters`` (mm) of each gear whose involute they
    cut (``d_b ≤ d_y ≤ d_a``): pressure angle there, arc thickness ``s_y`` and the chord
    with its height from the tip (``s̄_y``, ``h̄_y``)."""
    from mechloop.errors import HintedError
    from mechloop.gears.involute import (
        chordal_thickness,
        pressure_angle_on_circle,
        thickness_on_circle,
    )

    rows = []
    for d_y in diameters:
        for i, name in enumerate(("pinion", "wheel")):
            if pair.d_b[i] <= d_y <= pair.d_a[i]:
                s_y = float(thickness_on_circle(pair.s[i], pair.d[i], pair.alpha_n, d_y))
                chord, height = chordal_thickness(s_y, d_y, pair.d_a[i])
                alpha_y = float(pressure_angle_on_circle(pair.d_b[i], d_y))
                rows.append((name, d_y, np.degrees(alpha_y), s_y, float(chord),
                             float(height)))
    if not rows:
        raise HintedError(f"no circle of {', '.join(f'{d:g}' for d in diameters)} mm cuts "
                          "an involute of the pair",
                          f"take diameters between d_b and d_a: pinion "
                          f"{pair.d_b[0]:.4g}…{pair.d_a[0]:.4g}, wheel "
                          f"{pair.d_b[1]:.4g}…{pair.d_a[1]:.4g} mm")
    return pd.DataFrame(rows, columns=["gear", "d_y [mm]", "α_y [deg]", "s_y [mm]",
                                       "chord s̄_y [mm]", "height h̄_y [mm]"])


def train_table(train: PlanetaryTrain | WolfromTrain, speed_rpm: float) -> pd.DataFrame:
    """The analysis of one train: ratio, conditions and the speeds of its members."""
    if isinstance(train, WolfromTrain):
        return wolfrom_table(train, speed_rpm)
    speeds = train.speeds(speed_rpm * np.pi / 30.0)
    i, o, held = train.driver, train.output, train.fixed
    rows = [("Willis ratio i_ab^h", train.willis, ""),
            (f"ratio i_{i}{o} = ω_{i}/ω_{o} ({held} fixed)", train.ratio, ""),
            ("centre distance of the planets a_w", train.a_w, "mm"),
            ("coaxial (both rows at a_w)", float(train.coaxial), "1 = yes"),
            ("assembly number (whole: the planets fit)", train.assembly, ""),
            ("clearance between neighbouring planets", train.neighbour_margin, "mm")]
    rows += [(f"speed of {key}", value * 30.0 / np.pi, "rpm") for key, value in speeds.items()]
    return pd.DataFrame(rows, columns=["quantity", "value", "unit"])


def wolfrom_table(train: WolfromTrain, speed_rpm: float) -> pd.DataFrame:
    """The analysis of a Wolfrom train: both stages' ratios, the overall ratio, the
    conditions and the speeds of its members."""
    speeds = train.speeds(speed_rpm * np.pi / 30.0)
    first, second = train.assembly
    rows = [("first stage i_ah = 1 + z_b/z_a", train.carrier_ratio, ""),
            ("second stage, Willis i_eb^h = z_b z_f/(z_g z_e)", train.willis_be, ""),
            ("ratio i_ae = ω_a/ω_e (b fixed)", train.ratio, ""),
            ("centre distance of the planets a_w", train.a_w, "mm"),
            ("coaxial (all three meshes at a_w)", float(train.coaxial), "1 = yes"),
            ("assembly number (z_a + z_b)/k (whole: fits)", first, ""),
            ("assembly number (z_e z_g − z_b z_f)/(k gcd) (whole: fits)", second, ""),
            ("clearance between neighbouring planets", train.neighbour_margin, "mm")]
    rows += [(f"speed of {key}", value * 30.0 / np.pi, "rpm") for key, value in speeds.items()]
    return pd.DataFrame(rows, columns=["quantity", "value", "unit"])


def choice_table(choice: Choice | WolfromChoice, show: int | None = None) -> pd.DataFrame:
    """The designs of a choice, best first (``show`` of them, default all)."""
    n = len(choice) if show is None else min(show, len(choice))
    data = {"a": choice.z_a[:n], "g": choice.z_g[:n]}
    wolfrom = isinstance(choice, WolfromChoice)
    if wolfrom or choice.scheme.double:
        data["f"] = choice.z_f[:n]
    data["b"] = choice.z_b[:n]
    if wolfrom:
        data["e"] = choice.z_e[:n]
    name = "i_ae" if wolfrom else \
        f"i_{choice.driver}{output_member(choice.fixed, choice.driver)}"
    data |= {name: choice.ratio[:n],
             "error [%]": 100.0 * choice.error[:n], "size [modules]": choice.size[:n],
             "planet clearance [modules]": choice.margin[:n]}
    return pd.DataFrame(data)
