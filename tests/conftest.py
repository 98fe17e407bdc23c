"""Suite-wide settings.

Every property test draws a fixed, derandomized sequence of examples, so the README's test
command gives the same result on every machine, with or without ``CI`` set; set
``MECHLOOP_HYPOTHESIS=random`` to draw new examples each run (exploring locally).
``pyproject.toml`` turns every RuntimeWarning into an error: no NumPy warning may reach a
user.
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("fixed", derandomize=True, database=None)
if os.environ.get("MECHLOOP_HYPOTHESIS") != "random":
    settings.load_profile("fixed")

# The tests of English messages do not depend on the shell's language of messages
# (tests/test_messages_ru.py sets MECHLOOP_LANG where it wants Russian).
os.environ.pop("MECHLOOP_LANG", None)
