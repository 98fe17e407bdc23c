"""Russian entries of the message catalogue, one module per area of the library (each
module's ``ENTRIES``: see :mod:`mechloop.messages.ru.base` for the entry's form).  They come
before the catalogue's common entries, in the order of :data:`AREAS`: an entry should
match its own messages only (enough literal text in it)."""

from mechloop.messages.ru import dynamics, gears, model, synthesis, usage, views, web

AREAS = (model, dynamics, synthesis, gears, views, web, usage)
