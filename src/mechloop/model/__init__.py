"""The data model and its file format.

Owns: the vector model (:mod:`.schema`), its structural analysis (:mod:`.structure`),
validation with located errors (:mod:`.check`, :mod:`.load`, :mod:`.salvage`), the bounds
of a document read before it is expanded (:mod:`.limits`) and of every number in it
(:mod:`.numbers`), units (:mod:`.units`), argument tables and laws (:mod:`.tables`,
:mod:`.laws`).  Imports nothing from
``mechloop.solve`` or above.

Imports inside the package flow one way (``tests/test_model_imports.py``): the bottom is
:mod:`.numbers`, :mod:`.units`, :mod:`.signals`, :mod:`.roles`, :mod:`.expression`;
then the schema (:mod:`.dynamic`, :mod:`.elements`, :mod:`.synthesis`, :mod:`.schema`),
its analysis (:mod:`.structure` with :mod:`.block_guess`, :mod:`.check`), the document
layer (:mod:`.document`, :mod:`.salvage`), the group builder (the package
:mod:`.groups`) and on top the loader (:mod:`.load`), which gives
:meth:`~mechloop.model.schema.Model.from_dict` its reader.
This package imports the loader, so that the reader is set whichever module of the
package is imported first.
"""

from mechloop.model import load as _load  # noqa: F401  (sets the reader of Model.from_dict)
