"""The example models bundled with mechloop: their catalogue (``mechloop examples``) and a
copy to start from (``mechloop new``)."""

from mechloop.bundled.catalog import Example, examples, examples_dir, find_example
from mechloop.bundled.start import new_model

__all__ = ["Example", "examples", "examples_dir", "find_example", "new_model"]
