"""The compiled shortest round-trip formatter (mechloop.output.shortest) writes orjson's
text for every double, byte for byte: any bit pattern, subnormals, powers of ten and two,
integers around 2^53, the extremes, and the places where orjson's layout changes (the
point inside the digits, ``0.0000x``, the exponent form).  Independently of orjson, the
text reads back to the same double bit for bit and has the digits and exponent of
Python's repr (David Gay's shortest round-trip algorithm)."""

from __future__ import annotations

import numpy as np
import orjson
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from mechloop.output import schubfach
from mechloop.output.shortest import _eight, shortest_texts, write_int

#: Finite doubles from any bit pattern (NaN and infinities are not numbers' texts: the
#: writers write them as fixed words, tested in test_table_number_format.py).
BITS = st.integers(0, 2**64 - 1).map(lambda b: float(np.array(b, np.uint64).view(np.float64)))
FINITE = st.one_of(
    BITS.filter(np.isfinite),
    st.floats(allow_nan=False, allow_infinity=False, allow_subnormal=True),
    st.integers(-(2**63), 2**63).map(float),
    st.integers(-10**6, 10**6).map(lambda k: k / 10.0 ** (abs(k) % 23)),
    st.tuples(st.integers(1, 10**17), st.integers(-340, 310)).map(
        lambda me: float(f"{me[0]}e{me[1]}")).filter(np.isfinite),
)


def _orjson(values: np.ndarray) -> list[bytes]:
    return [orjson.dumps(float(v)) for v in values]


def _repr_digits(text: str) -> tuple[str, int]:
    """The significant digits and the decimal exponent of a number's text."""
    sign = text.startswith("-")
    mantissa, _, exponent = text.lstrip("-").partition("e")
    whole, _, part = mantissa.partition(".")
    figures = (whole + part).lstrip("0")
    point = len(whole) - (len(whole + part) - len(figures))
    return ("-" if sign else "") + (figures.rstrip("0") or "0"), \
        int(exponent or 0) + point if figures else 0


def _check(values: list[float]) -> None:
    array = np.array(values, dtype=np.float64)
    got = shortest_texts(array)
    assert got == _orjson(array)
    for text, value in zip(got, array, strict=True):
        back = np.float64(float(text))
        assert back.view(np.uint64) == value.view(np.uint64), (text, value)
        assert _repr_digits(text.decode()) == _repr_digits(repr(float(value))), text


@settings(max_examples=100, deadline=None)
@given(st.lists(FINITE, min_size=1, max_size=50))
def test_any_double_is_written_as_orjson_writes_it(values):
    _check(values)


def test_the_edges_and_every_layout():
    """Subnormals, the extremes, integers near 2^53, every power of two and of ten, and
    numbers of every digit count around each place where the layout changes."""
    values = [0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308, 2.225073858507201e-308,
              1.7976931348623157e308, -1.7976931348623157e308, 9007199254740993.0,
              9007199254740992.0, 9007199254740991.0, 0.1 + 0.2, 1 / 3, 1e-5, 1e-6, 1e-7,
              1e15, 1e16, 1e21, 1e22, 1e23, 123456789.12345679, 4.35, 2.0**-1074 * 3]
    values += [2.0**k for k in range(-1074, 1024)]
    values += [10.0**k for k in range(-323, 309)]
    values += [float(f"{m}e{k}") for k in range(-330, 309)
               for m in ("1", "1.5", "9.999999999999999", "1.2345678901234567", "5")]
    values += [float(i) for i in range(-1000, 1001)]
    values = [v for v in values if np.isfinite(v)]
    _check(values + [-v for v in values])


def test_a_million_random_bit_patterns():
    """orjson's text for 10^6 doubles of random bits, compared at once."""
    bits = np.random.default_rng(2018).integers(0, 2**64 - 1, size=1_000_000,
                                                dtype=np.uint64, endpoint=True)
    values = bits.view(np.float64)
    values = values[np.isfinite(values)]
    got = b",".join(shortest_texts(values))
    assert got == orjson.dumps(values, option=orjson.OPT_SERIALIZE_NUMPY)[1:-1]


@settings(max_examples=200, deadline=None)
@given(st.integers(-(2**63), 2**63 - 1))
def test_integers_in_decimal(value):
    out = np.zeros(24, dtype=np.uint8)
    end = write_int(np.int64(value), out, 2)
    assert out[2:end].tobytes() == str(value).encode()


def test_integers_at_every_digit_count():
    """Every power of ten and its neighbours, and the int64 extremes."""
    values = [0, 1, -1, 2**63 - 1, -(2**63), -(2**63) + 1]
    values += [s * (10**k + d) for k in range(19) for d in (-1, 0, 1) for s in (1, -1)]
    out = np.zeros(32, dtype=np.uint8)
    for value in values:
        end = write_int(np.int64(value), out, 3)
        assert out[3:end].tobytes() == str(value).encode()


def test_eight_digits_at_once_for_every_number_below_10_to_the_8():
    """The lane arithmetic giving eight ASCII digits in one word, for all 10^8 inputs,
    against the two four-digit texts Python writes for v // 10^4 and v % 10^4."""
    four = np.array([int.from_bytes(f"{i:04d}".encode(), "little") for i in range(10**4)],
                    dtype=np.uint64)
    assert _eight_digit_mismatches(four) == 0


@njit(cache=False)
def _eight_digit_mismatches(four: np.ndarray) -> int:
    bad = 0
    for v in range(100_000_000):
        expected = four[v // 10_000] | (four[v % 10_000] << np.uint64(32))
        bad += _eight(np.uint64(v)) != expected
    return bad


def test_values_as_a_results_table_has_them():
    """orjson's text for values with every count of significant digits (1 to 17) and
    every place of the point that tables have: m / 10^k is the double nearest the decimal
    m·10^-k (both exact), whose shortest digits are m's; m·10^k and 17-digit values too."""
    rng = np.random.default_rng(1)
    size = 400_000
    digits = rng.integers(1, 18, size=size)
    m = np.floor(rng.uniform(0, 1, size=size) * 10.0 ** digits) + 1
    k = rng.integers(0, 23, size=size)
    values = np.concatenate([m / 10.0 ** k, m * 10.0 ** rng.integers(0, 8, size=size),
                             rng.uniform(-1, 1, size=size) * 10.0 ** rng.integers(-7, 9, size)])
    values *= rng.choice([-1.0, 1.0], size=values.size)
    got = b",".join(shortest_texts(values))
    assert got == orjson.dumps(values, option=orjson.OPT_SERIALIZE_NUMPY)[1:-1]


def test_the_scaling_formulas_are_exact_over_every_exponent():
    """Schubfach's floor(log10 2^q), floor(log10(3/4 2^q)) and floor(log2 10^e) by integer
    multiplications equal the exact values for every binary exponent of a double, and the
    126-bit powers of ten g(k) lie in [2^125, 2^126) just above 10^-k 2^(125 - F)."""
    def floor_log10(numerator: int, denominator: int) -> int:
        k = len(str(numerator // denominator)) - 1 if numerator >= denominator else -1
        while 10 ** max(k, 0) * denominator > numerator * 10 ** max(-k, 0):
            k -= 1
        while 10 ** max(k + 1, 0) * denominator <= numerator * 10 ** max(-k - 1, 0):
            k += 1
        return k

    for q in range(schubfach.Q_MIN, 972):
        two = (1 << q, 1) if q >= 0 else (1, 1 << -q)
        assert (q * 661971961083) >> 41 == floor_log10(*two)
        three_quarters = (3 << q, 4) if q >= 0 else (3, 4 << -q)
        assert (q * 661971961083 - 274743187321) >> 41 == floor_log10(*three_quarters)
    for k in range(schubfach.K_MIN, schubfach.K_MAX + 1):
        assert (-k * 913124641741) >> 38 == schubfach.flog2pow10(-k)
        g = (int(schubfach._G[k - schubfach.K_MIN, 0]) << 63) + int(
            schubfach._G[k - schubfach.K_MIN, 1])
        assert 2**125 <= g < 2**126
        shift = 125 - schubfach.flog2pow10(-k)
        numerator = (10**-k if k <= 0 else 1) << max(shift, 0)
        exact = (numerator, (1 if k <= 0 else 10**k) << max(-shift, 0))
        assert (g - 1) * exact[1] <= exact[0] < g * exact[1]
