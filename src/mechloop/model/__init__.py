"""The data model and its file format.

Owns: the vector model (:mod:`.schema`), its structural analysis (:mod:`.structure`),
validation with located errors (:mod:`.check`, :mod:`.load`), units (:mod:`.units`),
argument tables and laws (:mod:`.tables`, :mod:`.laws`).  Imports nothing from
``mechloop.solve`` or above.
"""
