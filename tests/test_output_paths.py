"""Output paths: bad places are told before the run, the input model is not overwritten
without --force, and every file is written atomically with the mode it should have,
through symlinks, leaving no temporary file behind (even when the writer is killed)."""

from __future__ import annotations

import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.output import OutputError, atomic_file, atomic_write_bytes, check_output
from mechloop.output import atomic as atomic_module
from mechloop.output.paths import check_replaces_schema

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
runner = CliRunner()


def _model(tmp_path: Path, name: str = "m.json") -> Path:
    """The four-bar example, as YAML (with its comments) or JSON, in ``tmp_path``."""
    source = EXAMPLES / "four_bar.yaml"
    target = tmp_path / name
    if name.endswith(".json"):
        import yaml

        target.write_text(json.dumps(yaml.safe_load(source.read_text())))
    else:
        shutil.copy(source, target)
    return target


def _forbid(monkeypatch, module: str, name: str) -> None:
    """Make ``module.name`` fail the test if it is called: the check must come first."""
    def called(*args, **kwargs):
        raise AssertionError(f"{name} ran before the output path was checked")

    monkeypatch.setattr(f"{module}.{name}", called)


# ------------------------------------------------------------------ bad places, early


@pytest.mark.parametrize("command", [
    ["solve", "{model}", "-o", "{out}.csv"],
    ["sweep", "{model}", "--vary", "vectors.1.r=90:110:3", "--collect", "a3:max",
     "-o", "{out}.csv"],
    ["plot", "{model}", "plan", "-o", "{out}.png"],
    ["animate", "{model}", "-o", "{out}.gif"],
    ["report", "{model}", "-o", "{out}.pdf"],
    ["schema", "-o", "{out}.json"],
])
def test_a_missing_folder_is_an_error_before_the_run(tmp_path, monkeypatch, command):
    model = _model(tmp_path)
    _forbid(monkeypatch, "mechloop.model.load", "load_model")
    out = tmp_path / "no" / "such" / "folder" / "x"
    args = [a.format(model=model, out=out) for a in command]
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert f"the folder {tmp_path / 'no' / 'such' / 'folder'} does not exist" in result.output
    assert "mkdir -p" in result.output
    assert "Traceback" not in result.output


def test_a_folder_as_the_output_file_is_an_error(tmp_path, monkeypatch):
    model = _model(tmp_path)
    (tmp_path / "results.csv").mkdir()
    _forbid(monkeypatch, "mechloop.model.load", "load_model")
    for out in (tmp_path, tmp_path / "results.csv"):
        result = runner.invoke(app, ["solve", str(model), "-o", str(out)])
        assert result.exit_code == 2
        assert f"{out} is a folder, not a file" in result.output
        assert f"e.g. {out / 'results.csv'}" in result.output


def test_synthesis_checks_every_output_before_searching(tmp_path, monkeypatch):
    model = _model(tmp_path, "task.yaml")
    shutil.copy(EXAMPLES / "four_bar_path_synthesis.yaml", model)
    _forbid(monkeypatch, "mechloop.synthesis.search", "synthesize")
    for option, name in (("-o", "no/best.yaml"), ("--table", "no/best.csv"),
                         ("--plot", "no/c.png"), ("--fit", "no/f.png"),
                         ("--table", "best.txt"), ("-o", "best.csv")):
        result = runner.invoke(app, ["synthesize", str(model), option, str(tmp_path / name)])
        assert result.exit_code == 2, (option, name, result.output)
        assert ("does not exist" in result.output if name.startswith("no/")
                else "unknown output format" in result.output)


def test_a_read_only_folder_is_an_error(tmp_path, monkeypatch):
    folder = tmp_path / "locked"
    folder.mkdir()
    if os.geteuid() != 0:  # root writes anyway: then the permission test is simulated
        folder.chmod(0o555)
    else:
        real = os.access
        monkeypatch.setattr(os, "access", lambda p, mode: False if Path(p) == folder
                            else real(p, mode))
    try:
        with pytest.raises(OutputError) as caught:
            check_output(folder / "r.csv", suffixes=(".csv",))
    finally:
        folder.chmod(0o755)
    assert f"no permission to write in the folder {folder}" in str(caught.value)
    assert "choose a folder you can write to" in str(caught.value)


def test_a_failing_write_is_an_output_error_not_a_traceback():
    """/proc takes no new files, for root too: the error names the path and a fix."""
    with pytest.raises(OutputError) as caught:
        atomic_write_bytes("/proc/mechloop-test-output.csv", b"x")
    assert "cannot write /proc/mechloop-test-output.csv" in str(caught.value)
    assert "fix:" in str(caught.value)


# ------------------------------------------------------------------ the input model


@pytest.mark.parametrize("link", ["same", "symlink", "hardlink"])
def test_solve_does_not_overwrite_its_model(tmp_path, link):
    model = _model(tmp_path)
    before = model.read_bytes()
    out = tmp_path / "out.json"
    if link == "same":
        out = model
    elif link == "symlink":
        out.symlink_to(model)
    else:
        os.link(model, out)
    result = runner.invoke(app, ["solve", str(model), "-o", str(out)])
    assert result.exit_code == 2
    assert f"{out} is the input model {model}" in result.output
    assert "--force" in result.output
    assert model.read_bytes() == before
    forced = runner.invoke(app, ["solve", str(model), "-o", str(out), "--force"])
    assert forced.exit_code == 0, forced.output
    assert isinstance(json.loads(out.read_text()), list)  # the table replaced it


def test_synthesize_does_not_overwrite_its_model(tmp_path, monkeypatch):
    model = tmp_path / "task.yaml"
    shutil.copy(EXAMPLES / "four_bar_path_synthesis.yaml", model)
    before = model.read_bytes()
    _forbid(monkeypatch, "mechloop.synthesis.search", "synthesize")
    result = runner.invoke(app, ["synthesize", str(model), "-o", str(model)])
    assert result.exit_code == 2
    assert "is the input model" in result.output and "--force" in result.output
    assert model.read_bytes() == before  # comments and all


def test_plot_does_not_overwrite_its_model(tmp_path, monkeypatch):
    model = _model(tmp_path, "m.png")  # a model file may have any name
    _forbid(monkeypatch, "mechloop.model.load", "load_model")
    result = runner.invoke(app, ["plot", str(model), "plan", "-o", str(model)])
    assert result.exit_code == 2 and "is the input model" in result.output


def test_schema_refuses_to_replace_a_model_and_says_what_it_wrote(tmp_path):
    model = _model(tmp_path, "model.yaml")
    before = model.read_bytes()
    result = runner.invoke(app, ["schema", "-o", str(model)])
    assert result.exit_code == 2
    assert "holds no JSON Schema" in result.output and "--force" in result.output
    assert model.read_bytes() == before
    schema = tmp_path / "model.schema.json"
    for _ in range(2):  # a schema replaces an earlier schema without --force
        result = runner.invoke(app, ["schema", "-o", str(schema)])
        assert result.exit_code == 0 and result.output == f"wrote {schema}\n"
    assert "properties" in json.loads(schema.read_text())
    result = runner.invoke(app, ["schema", "-o", str(model), "--force"])
    assert result.exit_code == 0 and "properties" in json.loads(model.read_text())


def test_schema_may_replace_an_empty_file(tmp_path):
    empty = tmp_path / "s.json"
    empty.touch()
    check_replaces_schema(empty)
    check_replaces_schema(tmp_path / "new.json")
    (tmp_path / "model.json").write_text('{"vectors": {}, "contours": []}')
    with pytest.raises(OutputError):
        check_replaces_schema(tmp_path / "model.json")


# ------------------------------------------------------------------ mode, links, atomicity


@pytest.mark.parametrize("mask", [0o022, 0o077, 0o002])
def test_a_new_file_gets_0666_less_the_umask(tmp_path, mask):
    old = os.umask(mask)
    try:
        atomic_write_bytes(tmp_path / "new.csv", b"a\n")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "new.csv").stat().st_mode) == 0o666 & ~mask


@pytest.mark.parametrize("mode", [0o644, 0o640, 0o600, 0o664])
def test_a_replaced_file_keeps_its_mode(tmp_path, mode):
    target = tmp_path / "old.csv"
    target.write_bytes(b"old\n")
    target.chmod(mode)
    old = os.umask(0o077)
    try:
        atomic_write_bytes(target, b"new\n")
    finally:
        os.umask(old)
    assert target.read_bytes() == b"new\n"
    assert stat.S_IMODE(target.stat().st_mode) == mode


def test_cli_output_keeps_the_mode_of_the_file_it_replaces(tmp_path):
    model = _model(tmp_path)
    out = tmp_path / "r.csv"
    out.write_text("old")
    out.chmod(0o644)
    assert runner.invoke(app, ["solve", str(model), "-o", str(out)]).exit_code == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o644 and out.read_text() != "old"


def test_a_symlink_is_written_through(tmp_path):
    real = tmp_path / "data" / "real.csv"
    real.parent.mkdir()
    real.write_bytes(b"old\n")
    real.chmod(0o640)
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    atomic_write_bytes(link, b"new\n")
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert real.read_bytes() == b"new\n"
    assert stat.S_IMODE(real.stat().st_mode) == 0o640
    dangling = tmp_path / "dangling.csv"
    dangling.symlink_to(tmp_path / "data" / "later.csv")
    atomic_write_bytes(dangling, b"made\n")
    assert dangling.is_symlink() and (tmp_path / "data" / "later.csv").read_bytes() == b"made\n"
    assert sorted(p.name for p in real.parent.iterdir()) == ["later.csv", "real.csv"]


@pytest.mark.parametrize("scheme", ["anonymous", "copied", "named"])
def test_a_failed_write_leaves_the_old_file_and_nothing_else(tmp_path, monkeypatch, scheme):
    if scheme == "named":
        monkeypatch.setattr(atomic_module, "_ANONYMOUS", False)
    elif scheme == "copied":
        monkeypatch.setattr(atomic_module, "_link", lambda fd, name: False)
    target = tmp_path / "t.csv"
    target.write_bytes(b"old\n")
    with pytest.raises(RuntimeError), atomic_file(target) as handle:
        handle.write(b"half")
        handle.flush()
        assert target.read_bytes() == b"old\n"  # never half written
        raise RuntimeError("writer failed")
    assert target.read_bytes() == b"old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]
    with atomic_file(target) as handle:  # and a good write by the same scheme
        handle.write(b"new\n")
    assert target.read_bytes() == b"new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]
    assert stat.S_IMODE(target.stat().st_mode) == 0o666 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


_KILLED_WRITER = textwrap.dedent("""
    import sys, time
    from mechloop.output import atomic
    if sys.argv[2] == "named":
        atomic._ANONYMOUS = False
    with atomic.atomic_file(sys.argv[1]) as handle:
        handle.write(b"x" * 100000)
        handle.flush()
        print("writing", flush=True)
        time.sleep(60)
""")


@pytest.mark.parametrize(("scheme", "sig"), [
    pytest.param("anonymous", signal.SIGKILL, marks=pytest.mark.skipif(
        not hasattr(os, "O_TMPFILE"), reason="needs O_TMPFILE (Linux)")),
    ("named", signal.SIGTERM),
])
def test_a_killed_writer_leaves_no_temporary_file(tmp_path, scheme, sig):
    target = tmp_path / "big.csv"
    target.write_bytes(b"old\n")
    child = subprocess.Popen([sys.executable, "-c", _KILLED_WRITER, str(target), scheme],
                             stdout=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline() == "writing\n"
        assert len(list(tmp_path.iterdir())) == (1 if scheme == "anonymous" else 2)
        child.send_signal(sig)
        child.wait(timeout=30)
    finally:
        child.kill()
        child.wait()
    assert [p.name for p in tmp_path.iterdir()] == ["big.csv"]
    assert target.read_bytes() == b"old\n"


def test_solve_does_not_overwrite_a_csv_table_its_model_reads(tmp_path, monkeypatch):
    table = tmp_path / "crank.csv"
    table.write_text("position,angle\n0,0\n72,360\n")
    model = tmp_path / "m.yaml"
    model.write_text((EXAMPLES / "four_bar.yaml").read_text().replace(
        "1: {table: {0: 0, 72: 360}}", "1: {csv: crank.csv}"))
    assert runner.invoke(app, ["check", str(model)]).exit_code == 0
    _forbid(monkeypatch, "mechloop.model.load", "load_model")
    result = runner.invoke(app, ["solve", str(model), "-o", str(table)])
    assert result.exit_code == 2
    assert f"is a table the model reads, {table}" in result.output
    assert table.read_text() == "position,angle\n0,0\n72,360\n"


def test_an_error_of_the_callers_own_is_not_told_as_a_disk_error(tmp_path):
    """Only the disk's errors become an OutputError; a broken pipe from an encoder the
    caller runs inside the block propagates as it is, and nothing is left behind."""
    target = tmp_path / "cycle.mp4"
    with pytest.raises(BrokenPipeError), atomic_file(target) as handle:
        handle.write(b"frames")
        raise BrokenPipeError(32, "Broken pipe")
    assert list(tmp_path.iterdir()) == []


def test_a_full_disk_is_an_output_error(tmp_path):
    import errno

    target = tmp_path / "r.csv"
    with pytest.raises(OutputError, match="free some disk space"), \
            atomic_file(target) as handle:
        handle.write(b"x")
        raise OSError(errno.ENOSPC, "No space left on device")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0,
                    reason="changing a file's owner needs root")
@pytest.mark.parametrize("scheme", ["anonymous", "copied", "named"])
def test_a_replaced_file_keeps_its_owner_by_every_scheme(tmp_path, monkeypatch, scheme):
    """Also when the anonymous file has to be copied to a named one (no /proc link)."""
    monkeypatch.setattr(atomic_module, "_ANONYMOUS", True)  # a copy turns it off
    if scheme == "named":
        monkeypatch.setattr(atomic_module, "_ANONYMOUS", False)
    elif scheme == "copied":
        monkeypatch.setattr(atomic_module, "_link", lambda fd, name: False)
    target = tmp_path / "t.csv"
    target.write_bytes(b"old\n")
    os.chown(target, 1234, 2345)
    target.chmod(0o640)
    atomic_write_bytes(target, b"new\n")
    st = target.stat()
    assert (st.st_uid, st.st_gid, stat.S_IMODE(st.st_mode)) == (1234, 2345, 0o640)
    assert target.read_bytes() == b"new\n" and [p.name for p in tmp_path.iterdir()] == ["t.csv"]


@pytest.mark.skipif(not hasattr(os, "O_TMPFILE"), reason="needs O_TMPFILE (Linux)")
def test_a_copy_that_stops_short_is_an_error_not_a_short_file(tmp_path, monkeypatch):
    monkeypatch.setattr(atomic_module, "_ANONYMOUS", True)
    monkeypatch.setattr(atomic_module, "_link", lambda fd, name: False)
    monkeypatch.setattr(atomic_module.os, "sendfile", lambda out, src, at, n: 0)
    target = tmp_path / "t.csv"
    target.write_bytes(b"old\n")
    with pytest.raises(OutputError, match="copied 0 of 8 bytes"):
        atomic_write_bytes(target, b"content\n")
    assert target.read_bytes() == b"old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]


def test_a_large_file_is_written_back_while_it_is_written(tmp_path, monkeypatch):
    """The writeback thread asks for the new bytes to go to the disk as they come (so
    that the final fsync waits for the last ones only) and is gone before the file is
    synced and named, also when the writer fails."""
    import threading
    import time
    from itertools import pairwise

    if atomic_module._sync_file_range() is None:
        pytest.skip("no sync_file_range here")
    asked: list[tuple[int, int]] = []
    monkeypatch.setattr(atomic_module, "WRITEBACK_BYTES", 1000)
    monkeypatch.setattr(atomic_module, "WRITEBACK_SECONDS", 0.001)
    monkeypatch.setattr(atomic_module._Writeback, "_call",
                        lambda fd, offset, length: asked.append((offset, length)) or 0)
    monkeypatch.setattr(atomic_module._Writeback, "_looked", True)
    target = tmp_path / "big.bin"
    with atomic_file(target) as handle:
        for _ in range(5):
            handle.write(b"x" * 3000)
            handle.flush()
            deadline = time.monotonic() + 5
            while sum(length for _, length in asked) < handle.tell() and \
                    time.monotonic() < deadline:
                time.sleep(0.001)
    assert target.read_bytes() == b"x" * 15000
    assert asked[0][0] == 0 and all(a + n == b for (a, n), (b, _) in pairwise(asked))
    assert sum(length for _, length in asked) == 15000
    assert not [t for t in threading.enumerate() if t.name == "mechloop-writeback"]
    with pytest.raises(RuntimeError), atomic_file(tmp_path / "failed.bin") as handle:
        handle.write(b"y" * 5000)
        raise RuntimeError("writer failed")
    assert not [t for t in threading.enumerate() if t.name == "mechloop-writeback"]
    assert [p.name for p in tmp_path.iterdir()] == ["big.bin"]
