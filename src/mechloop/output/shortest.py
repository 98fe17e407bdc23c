"""The shortest text of a double that reads back to it, in compiled code without Python's lock.

:func:`write_double` writes a finite double into a byte buffer exactly as orjson writes it
(the form the table writers have always used): the shortest decimal digits that read back
to the same double, bit for bit, the one nearest the double among them (found by
:func:`mechloop.output.schubfach.shortest_decimal`), laid out as orjson lays them out:

- ``kk``, the place of the decimal point after the first digit (10^(kk-1) <= |x| < 10^kk):
  digits then zeros and ``.0`` for an integer of at most 16 figures (``100.0``,
  ``1000000000000000.0``); digits with a point inside for 0 < kk <= 16 (``12.34``);
  ``0.`` and zeros for -5 < kk <= 0 (``0.00001``); else ``d.ddde±x`` with the exponent's
  sign always written and no leading zeros (``1e-7``, ``1.5e+300``, ``5e-324``);
- ``0.0`` and ``-0.0`` for the zeros, a ``-`` before a negative number.

The digits are written eight at a time from one word (:func:`_eight`).  :func:`write_int`
writes an int64 in decimal.  Everything is compiled with ``nogil``: threads format
disjoint rows at once (:mod:`mechloop.output.lines`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from mechloop.output.memory import address_of, load8, load_uint8, store1, store8
from mechloop.output.schubfach import shortest_decimal

#: Bytes :func:`write_double` may touch from where it writes.
SLACK = 40

_U0, _U1, _U10, _U100 = np.uint64(0), np.uint64(1), np.uint64(10), np.uint64(100)
_U1E4, _U1E8 = np.uint64(10**4), np.uint64(10**8)
_POW10 = np.array([10**k for k in range(20)], dtype=np.uint64)
_MANTISSA = np.uint64((1 << 52) - 1)
_EXPONENT = np.uint64(0x7FF)
_SIGN = np.uint64(1 << 63)
_U52 = np.uint64(52)
_ZEROS = np.uint64(int.from_bytes(b"00000000", "little"))
_ZERO_TEXT = np.uint64(int.from_bytes(b"0.000000", "little"))  # "0.0" and slack
_POINT_ZERO = np.uint64(int.from_bytes(b".0000000", "little"))  # ".0" and slack
_ASCII_ZEROS = _ZEROS
_U8, _U16, _U20, _U32 = np.uint64(8), np.uint64(16), np.uint64(20), np.uint64(32)
_U103, _U10486 = np.uint64(103), np.uint64(10486)
_U1E16 = np.uint64(10**16)
_LANES32 = np.uint64(0x0000007F0000007F)
_LANES16 = np.uint64(0x000F000F000F000F)
_POINT_ZEROS = np.uint64(int.from_bytes(b"0.000000", "little"))


@njit(nogil=True, cache=True, error_model="numpy", inline="always")
def _length(v: np.uint64) -> int:
    """Decimal digits of v (1 for 0): a sum of comparisons (no branch to mispredict)."""
    n = 1
    for k in range(1, 20):
        n += v >= _POW10[k]
    return n


@njit(nogil=True, cache=True, error_model="numpy", inline="always")
def _eight(v: np.uint64) -> np.uint64:
    """The eight decimal digits of v < 10^8 (leading zeros kept) as ASCII in a uint64,
    the first digit in the lowest byte (little-endian memory order): quotients by 10^4,
    100 and 10 taken in every lane at once (the divisions by 100 and 10 as multiplications
    exact below 10^4 and 100)."""
    high = v // _U1E4
    merged = high | ((v - _U1E4 * high) << _U32)  # two 32-bit lanes: v / 10^4, v % 10^4
    q = ((merged * _U10486) >> _U20) & _LANES32
    merged = q | ((merged - _U100 * q) << _U16)  # four 16-bit lanes: two digits each
    q = ((merged * _U103) >> _U10) & _LANES16
    return (q | ((merged - _U10 * q) << _U8)) + _ASCII_ZEROS


@njit(nogil=True, cache=True, error_model="numpy")
def _put_digits(v: np.uint64, address: int, length: int) -> None:
    """The ``length`` decimal digits of v (``length`` = :func:`_length` of v) written at
    ``address``, in whole 8-byte words (up to 8 bytes past the digits are overwritten)."""
    if length <= 8:
        store8(address, _eight(v) >> np.uint64(8 * (8 - length)))
    elif length <= 16:
        high = v // _U1E8
        store8(address, _eight(high) >> np.uint64(8 * (16 - length)))
        store8(address + length - 8, _eight(v - _U1E8 * high))
    else:
        top = v // _U1E16
        rest = v - _U1E16 * top
        high = rest // _U1E8
        store8(address, _eight(top) >> np.uint64(8 * (24 - length)))
        store8(address + length - 16, _eight(high))
        store8(address + length - 8, _eight(rest - _U1E8 * high))


@njit(nogil=True, cache=True, error_model="numpy")
def write_double_at(bits: np.uint64, base: int) -> int:
    """Write the finite double with bit pattern ``bits`` at memory address ``base`` as
    orjson writes it (see the module); the address after it.  SLACK bytes from ``base``
    must be writable (the text takes at most 24; whole 8-byte words are written)."""
    if bits & _SIGN:
        store1(base, 45)  # "-"
        base += 1
    ieee_mantissa = bits & _MANTISSA
    ieee_exponent = int((bits >> _U52) & _EXPONENT)
    if ieee_exponent == 0 and ieee_mantissa == _U0:
        store8(base, _ZERO_TEXT)
        return base + 3
    mantissa, exponent = shortest_decimal(ieee_mantissa, ieee_exponent)
    length = _length(mantissa)
    kk = length + exponent  # 10^(kk-1) <= |x| < 10^kk
    if 0 <= exponent and kk <= 16:  # 1234e7 -> 12340000000.0
        _put_digits(mantissa, base, length)
        store8(base + length, _ZEROS)  # kk - length <= 15 zeros
        store8(base + length + 8, _ZEROS)
        store8(base + kk, _POINT_ZERO)
        return base + kk + 2
    if 0 < kk <= 16:  # 1234e-2 -> 12.34: the fraction moved right by one for the point
        _put_digits(mantissa, base, length)
        low = load8(base + kk)
        high = load8(base + kk + 8)
        store8(base + kk + 1, low)
        store8(base + kk + 9, high)
        store1(base + kk, 46)
        return base + length + 1
    if -5 < kk <= 0:  # 1234e-6 -> 0.001234
        store8(base, _POINT_ZEROS)
        _put_digits(mantissa, base + 2 - kk, length)
        return base + 2 - kk + length
    if length == 1:  # 1e30
        store1(base, 48 + int(mantissa))
        return _write_exponent(kk - 1, base + 1)
    _put_digits(mantissa, base + 1, length)  # 1234e30 -> 1.234e33
    store1(base, load_uint8(base + 1))
    store1(base + 1, 46)
    return _write_exponent(kk - 1, base + length + 1)


@njit(nogil=True, cache=True, error_model="numpy")
def write_double(bits: np.uint64, out: np.ndarray, at: int) -> int:
    """:func:`write_double_at` into ``out`` (uint8) from index ``at`` (SLACK bytes from
    it); the index after the text."""
    base = address_of(out)
    return write_double_at(bits, base + at) - base


@njit(nogil=True, cache=True, error_model="numpy")
def _write_exponent(e: int, address: int) -> int:
    """``e+x`` or ``e-x`` (no leading zeros) at ``address``; the address after it."""
    store1(address, 101)  # "e"
    store1(address + 1, 45 if e < 0 else 43)  # "-" or "+"
    e = -e if e < 0 else e
    if e >= 100:
        store1(address + 2, 48 + e // 100)
        store1(address + 3, 48 + (e // 10) % 10)
        store1(address + 4, 48 + e % 10)
        return address + 5
    if e >= 10:
        store1(address + 2, 48 + e // 10)
        store1(address + 3, 48 + e % 10)
        return address + 4
    store1(address + 2, 48 + e)
    return address + 3


@njit(nogil=True, cache=True, error_model="numpy")
def write_int_at(value: np.int64, address: int) -> int:
    """Write an int64 in decimal at memory address ``address`` (24 writable bytes); the
    address after it."""
    if value < 0:
        store1(address, 45)
        address += 1
        magnitude = np.uint64(-(value + 1)) + _U1  # also for -2^63
    else:
        magnitude = np.uint64(value)
    length = _length(magnitude)
    _put_digits(magnitude, address, length)
    return address + length


@njit(nogil=True, cache=True, error_model="numpy")
def write_int(value: np.int64, out: np.ndarray, at: int) -> int:
    """Write an int64 in decimal into ``out`` from ``at`` (24 bytes needed); the index
    after it."""
    base = address_of(out)
    return write_int_at(value, base + at) - base


@njit(nogil=True, cache=True, error_model="numpy")
def _format_all(bits: np.ndarray, out: np.ndarray, ends: np.ndarray) -> None:
    at = 0
    for i in range(bits.size):
        at = write_double(bits[i], out, at)
        ends[i] = at


def shortest_texts(values: np.ndarray) -> list[bytes]:
    """The text :func:`write_double` gives every value of a float64 array (finite values
    only): for tests and checks."""
    values = np.ascontiguousarray(values, dtype=np.float64).ravel()
    if not np.isfinite(values).all():
        raise ValueError("shortest_texts formats finite values only")
    out = np.empty(24 * values.size + SLACK, dtype=np.uint8)
    ends = np.empty(values.size, dtype=np.int64)
    _format_all(values.view(np.uint64), out, ends)
    text = out.tobytes()
    starts = np.concatenate(([0], ends[:-1]))
    return [text[s:e] for s, e in zip(starts.tolist(), ends.tolist(), strict=True)]
