"""A small arithmetic language for loads: ``"-2000*sign(dr6)*(r6 > 0.6)"``.

The text is parsed by :mod:`ast` and *interpreted* node by node — never compiled or run
by Python: numbers, names, ``+ − * / ** %``, unary minus, comparisons (giving 0 or 1)
and calls of the functions in :data:`FUNCTIONS`.  Anything else (attributes, subscripts,
keywords, strings, lambdas...) is refused when the model is read, with the node named.
Values are NumPy arrays (or floats), so one evaluation covers all positions.
"""

from __future__ import annotations

import ast
import operator
import re

import numpy as np

#: Functions an expression may call.
FUNCTIONS = {name: getattr(np, name) for name in (
    "sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "sqrt", "exp", "log",
    "abs", "sign", "minimum", "maximum", "where", "hypot", "tanh")}
FUNCTIONS.update(min=np.minimum, max=np.maximum)
CONSTANTS = {"pi": np.pi}
#: Names of the state: ``t`` (s), ``rK``/``aK`` (m, rad), their rates ``drK``/``daK``.
STATE_NAME = re.compile(r"^(t|d?[ra][1-9][0-9]{0,5})$")
MAX_CHARS = 400

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.Pow: operator.pow, ast.Mod: operator.mod}
_COMPARE = {ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt,
            ast.GtE: operator.ge}


class Expression:
    """A parsed expression; :attr:`names` are the state names it reads."""

    def __init__(self, text: str):
        if len(text) > MAX_CHARS:
            raise ValueError(f"an expression of at most {MAX_CHARS} characters")
        try:
            tree = ast.parse(text.strip(), mode="eval")
        except (SyntaxError, ValueError, RecursionError) as exc:
            raise ValueError(f"cannot read {text!r}: {exc}") from None
        names: set[str] = set()
        for node in ast.walk(tree):
            _check(node, names)
        self.text = text
        self.tree = tree.body
        self.names = frozenset(names)

    def __call__(self, values: dict[str, object]):
        """The value for ``values`` (a number or array per name in :attr:`names`)."""
        with np.errstate(all="ignore"):
            return np.asarray(_eval(self.tree, values), dtype=float)


def _check(node: ast.AST, names: set[str]) -> None:
    if isinstance(node, ast.Expression | ast.Load | ast.operator | ast.unaryop
                  | ast.cmpop):
        if isinstance(node, ast.operator) and type(node) not in _BINARY:
            raise ValueError(f"operator {type(node).__name__} is not allowed")
        if isinstance(node, ast.cmpop) and type(node) not in _COMPARE:
            raise ValueError(f"comparison {type(node).__name__} is not allowed")
        if isinstance(node, ast.unaryop) and not isinstance(node, ast.USub | ast.UAdd):
            raise ValueError(f"operator {type(node).__name__} is not allowed")
        return
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, int | float):
            raise ValueError(f"{node.value!r} is not a number")
        return
    if isinstance(node, ast.Name):
        if node.id in FUNCTIONS:
            return
        if node.id not in CONSTANTS:
            if not STATE_NAME.match(node.id):
                raise ValueError(f"unknown name {node.id!r}: use t, rK, aK, drK, daK, pi "
                                 "and the functions " + ", ".join(sorted(FUNCTIONS)))
            names.add(node.id)
        return
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS \
                or node.keywords:
            raise ValueError("only calls like sin(x) of " + ", ".join(sorted(FUNCTIONS)))
        return
    if isinstance(node, ast.BinOp | ast.UnaryOp):
        return
    if isinstance(node, ast.Compare) and len(node.ops) == 1:
        return
    raise ValueError(f"{type(node).__name__} is not allowed in an expression")


def _eval(node: ast.AST, values: dict[str, object]):
    if isinstance(node, ast.Constant):
        return np.float64(node.value)  # NumPy arithmetic: overflow gives inf, not an error
    if isinstance(node, ast.Name):
        return CONSTANTS[node.id] if node.id in CONSTANTS else values[node.id]
    if isinstance(node, ast.BinOp):
        return _BINARY[type(node.op)](_eval(node.left, values), _eval(node.right, values))
    if isinstance(node, ast.UnaryOp):
        value = _eval(node.operand, values)
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.Compare):
        test = _COMPARE[type(node.ops[0])](_eval(node.left, values),
                                           _eval(node.comparators[0], values))
        return np.asarray(test, dtype=float)
    return FUNCTIONS[node.func.id](*(_eval(a, values) for a in node.args))
