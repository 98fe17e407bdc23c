"""Raw memory access in compiled code: loads and stores at addresses, any alignment.

The number formatter and the line builder write whole 8-byte words into buffers that have
slack past the text (fewer, wider stores than byte by byte) and read table columns where
they lie (their addresses and strides).  These are numba intrinsics: a single LLVM load or
store each, without an array's index checks.
"""

from __future__ import annotations

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.extending import intrinsic


@intrinsic
def load8(typingctx, address):
    """The 8 bytes at a memory address (any alignment), as a uint64 (little-endian)."""
    def codegen(context, builder, signature, args):
        pointer = builder.inttoptr(args[0], ir.IntType(64).as_pointer())
        return builder.load(pointer, align=1)

    return types.uint64(types.intp), codegen


@intrinsic
def store8(typingctx, address, word):
    """Store a uint64's 8 bytes at a memory address (any alignment)."""
    def codegen(context, builder, signature, args):
        pointer = builder.inttoptr(args[0], ir.IntType(64).as_pointer())
        builder.store(args[1], pointer, align=1)
        return context.get_dummy_value()

    return types.none(types.intp, types.uint64), codegen


@intrinsic
def store1(typingctx, address, byte):
    """Store one byte (the low 8 bits of an integer) at a memory address."""
    def codegen(context, builder, signature, args):
        pointer = builder.inttoptr(args[0], ir.IntType(8).as_pointer())
        value = args[1]
        if value.type.width > 8:
            value = builder.trunc(value, ir.IntType(8))
        builder.store(value, pointer)
        return context.get_dummy_value()

    return types.none(types.intp, byte), codegen


@intrinsic
def load_uint8(typingctx, address):
    """The byte at a memory address."""
    def codegen(context, builder, signature, args):
        pointer = builder.inttoptr(args[0], ir.IntType(8).as_pointer())
        return builder.load(pointer)

    return types.uint8(types.intp), codegen


@njit(nogil=True, cache=True)
def address_of(array) -> int:
    """The address of an array's first element as an intp (numba types ``ctypes.data`` as
    uintp: mixed with signed offsets it would turn into a float)."""
    return np.intp(array.ctypes.data)
