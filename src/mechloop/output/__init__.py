"""Writing files: every file mechloop writes goes through this package.

Owns: the atomic writer (:mod:`.atomic`: a file appears whole or not at all, keeps the
mode of the file it replaces, writes through a symlink, leaves no temporary file behind),
the checks of an output path before a long run (:mod:`.paths`: the folder exists and is
writable, the path is no folder, the input model and its CSV tables are not
overwritten) and the streaming
table writers (:mod:`.tables`: CSV, JSON, Parquet and XLSX in bounded memory; large tables
of numbers formatted in compiled code on threads, :mod:`.lines`, every float by the
shortest round-trip formatter :mod:`.shortest`; Parquet by :mod:`.parquet`, from the
table's memory).

May import: :mod:`mechloop.errors`, NumPy, pandas, orjson, pyarrow and numba (the last
four only inside the functions that need them, so that the command line starts fast), and
:func:`mechloop.model.load.read_document` inside the function that lists the files a
model reads.
"""

from mechloop.output.atomic import atomic_file, atomic_path, atomic_write_bytes, atomic_write_text
from mechloop.output.paths import OutputError, check_output

__all__ = ["OutputError", "atomic_file", "atomic_path", "atomic_write_bytes",
           "atomic_write_text", "check_output"]
