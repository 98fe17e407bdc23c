"""The word of the unknown role: a vector parameter written ``function`` is solved by its
contour.  Kept apart from :mod:`.schema` so that the modules the schema is built from
(:mod:`.synthesis`) can test a role without importing the schema back.
"""

from __future__ import annotations

#: The role of an unknown vector parameter (``r: function``, ``a: function``).
FUNCTION = "function"


def is_function(role: object) -> bool:
    """Whether ``role`` is the unknown role ``"function"`` (surrounding spaces allowed)."""
    return isinstance(role, str) and role.strip() == FUNCTION
