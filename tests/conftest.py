"""Suite-wide settings.

Under CI (``CI`` set, as ``.ci/run`` is run) every property test draws a fixed,
derandomized sequence of examples, so a submission's result does not depend on chance;
locally they draw new examples each run.  ``pyproject.toml`` turns every RuntimeWarning
into an error: no NumPy warning may reach a user.
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

# The tests of English messages do not depend on the shell's language of messages
# (tests/test_messages_ru.py sets MECHLOOP_LANG where it wants Russian).
os.environ.pop("MECHLOOP_LANG", None)
