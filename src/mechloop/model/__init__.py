"""The data model and its file format.

Owns: the vector model (:mod:`.schema`), its structural analysis (:mod:`.structure`),
validation with located errors (:mod:`.check`, :mod:`.load`, :mod:`.salvage`), the bounds
of a document read before it is expanded (:mod:`.limits`) and of every number in it
(:mod:`.numbers`), units (:mod:`.units`), argument tables and laws (:mod:`.tables`,
:mod:`.laws`).  Imports nothing from
``mechloop.solve`` or above.
"""
