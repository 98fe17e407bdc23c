"""The shortest decimal of a double that reads back to it: Schubfach, without loops.

:func:`shortest_decimal` gives the digits and the exponent of ten of the decimal with the
fewest significant digits inside a finite nonzero double's rounding interval, the one
nearest the double among them (ties to an even last digit): the decimal Ryu, David Gay's
``repr`` and orjson give.  The method is Raffaello Giulietti's Schubfach ("The Schubfach
way to render doubles", 2020; the algorithm of Java's ``Double.toString`` since JDK 19,
``jdk.internal.math.DoubleToDecimal.toDecimal``): the double c·2^q and the ends of its
interval are scaled by 10^-k (k = floor(log10 2^q)) with one 126-bit power of ten ``g``
each, rounded to odd, so the scaled values have exactly the information needed to pick
the decimal with one digit fewer than the scale's, or the nearer of the two at the scale —
three multiplications, no loop on digits.  Java renders at least two digits (``4.9E-324``,
hence its test ``s >= 100`` and its scaling of the smallest subnormals); here the decimal
with one digit fewer is tried from ``s >= 10``, so every double gets the shortest
(``5e-324``): the interval is narrower than 10^(k+1) (10^k <= 2^q < 10^(k+1)), so it holds
at most one multiple of 10^(k+1), and a decimal shorter still would be one of those.

The table of ``g`` (k from -324 to 292, each as its top 63 bits and its low 63 bits) is
computed exactly at import with Python's integers.
"""

from __future__ import annotations

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.extending import intrinsic

K_MIN, K_MAX = -324, 292
Q_MIN = -1074
_MASK63 = (1 << 63) - 1


def flog2pow10(e: int) -> int:
    """floor(log2(10^e)), exactly."""
    return (10**e).bit_length() - 1 if e >= 0 else -(10**-e).bit_length()


def _table() -> np.ndarray:
    """g(k) = floor(10^-k · 2^(125 - flog2pow10(-k))) + 1 for K_MIN <= k <= K_MAX, in
    [2^125, 2^126): rows (g >> 63, g & (2^63 - 1))."""
    table = np.zeros((K_MAX - K_MIN + 1, 2), dtype=np.uint64)
    for k in range(K_MIN, K_MAX + 1):
        shift = 125 - flog2pow10(-k)
        if k <= 0:
            g = 10**-k << shift if shift >= 0 else 10**-k >> -shift
        else:
            g = (1 << shift) // 10**k
        g += 1
        table[k - K_MIN] = g >> 63, g & _MASK63
    return table


_G = _table()
_C_MIN = np.uint64(1 << 52)
_MANTISSA = np.uint64((1 << 52) - 1)
_U0, _U1, _U2, _U10 = np.uint64(0), np.uint64(1), np.uint64(2), np.uint64(10)


@intrinsic
def _round_to_odd(typingctx, g1, g0, cp):
    """floor(g · cp / 2^127) with its last bit set when the rest is not zero (as Java's
    ``rop``: g = g1·2^63 + g0, g1 and g0 below 2^63, cp below 2^63), as a uint64."""
    def codegen(context, builder, signature, args):
        wide, word = ir.IntType(128), ir.IntType(64)
        g1_, g0_, cp_ = (builder.zext(x, wide) for x in args)
        sixty_four = ir.Constant(wide, 64)
        x1 = builder.trunc(builder.lshr(builder.mul(g0_, cp_), sixty_four), word)
        y = builder.mul(g1_, cp_)
        y0 = builder.trunc(y, word)
        y1 = builder.trunc(builder.lshr(y, sixty_four), word)
        z = builder.add(builder.lshr(y0, ir.Constant(word, 1)), x1)
        vbp = builder.add(y1, builder.lshr(z, ir.Constant(word, 63)))
        mask = ir.Constant(word, _MASK63)
        sticky = builder.lshr(builder.add(builder.and_(z, mask), mask), ir.Constant(word, 63))
        return builder.or_(vbp, sticky)

    return types.uint64(types.uint64, types.uint64, types.uint64), codegen


@njit(nogil=True, cache=True, error_model="numpy", inline="always")
def shortest_decimal(ieee_mantissa: np.uint64, ieee_exponent: int) -> tuple[np.uint64, int]:
    """The shortest decimal (digits without trailing zeros, exponent of ten) of the finite
    nonzero double with these mantissa bits and biased exponent."""
    if ieee_exponent == 0:
        c = ieee_mantissa
        q = Q_MIN
    else:
        c = _C_MIN | ieee_mantissa
        q = ieee_exponent - 1075
        if -53 < q < 0:  # an integer below 2^53 is its own shortest decimal
            f = c >> np.uint64(-q)
            if f << np.uint64(-q) == c:
                return _trimmed(f, 0)
    odd = c & _U1
    cb = c << _U2
    cbr = cb + _U2
    if c != _C_MIN or q == Q_MIN:
        cbl = cb - _U2
        k = (q * 661971961083) >> 41  # floor(log10 2^q)
    else:  # the gap below a power of two is half the gap above it
        cbl = cb - _U1
        k = (q * 661971961083 - 274743187321) >> 41  # floor(log10(3/4 2^q))
    h = np.uint64(q + ((-k * 913124641741) >> 38) + 2)  # flog2pow10(-k)
    g1 = _G[k - K_MIN, 0]
    g0 = _G[k - K_MIN, 1]
    vb = _round_to_odd(g1, g0, cb << h)
    vbl = _round_to_odd(g1, g0, cbl << h)
    vbr = _round_to_odd(g1, g0, cbr << h)
    s = vb >> _U2
    t = s + _U1
    uin = vbl + odd <= s << _U2
    win = (t << _U2) + odd <= vbr
    sp10 = _U10 * (s // _U10)
    tp10 = sp10 + _U10
    upin = vbl + odd <= sp10 << _U2
    wpin = (tp10 << _U2) + odd <= vbr
    twice = (s + t) << _U1
    if s >= _U10 and upin != wpin:  # one digit fewer: s rounded down or up to a multiple of 10
        f = sp10 if upin else tp10
    elif uin != win:
        f = s if uin else t
    elif vb < twice or (vb == twice and (s & _U1) == _U0):  # both inside: the nearer,
        f = s                                                # ties to even
    else:
        f = t
    return _trimmed(f, k)


@njit(nogil=True, cache=True, error_model="numpy")
def _trimmed(f: np.uint64, e: int) -> tuple[np.uint64, int]:
    """f·10^e with f's trailing zeros moved into the exponent."""
    while True:
        q = f // _U10
        if f - _U10 * q != _U0:
            return f, e
        f = q
        e += 1
