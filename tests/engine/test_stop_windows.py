"""A stop signal can raise between any two steps of the outputs' staging, right after a folder or a temporary file
was made, until the outputs start moving into place (from then on the command line ignores stop signals,
formats.BEFORE_MOVES). Each step is interrupted in turn (the signal stands in as KeyboardInterrupt, raised right after
the n-th os.mkdir, os.open or os.replace returned, unless the moves have begun): the folder must then hold what it
held before, whole, and nothing else; a run not interrupted writes every output and leaves nothing hidden."""

import os

import pytest

from abm_workbench import formats
from abm_workbench.formats import replacing
from abm_workbench.jobs.run import output_folders
from abm_workbench.report.staging import staged


def _listing(folder):
    """{relative path: text or None for a folder} of everything under `folder`, hidden entries included."""
    found = {}
    for root, folders, files in os.walk(folder):
        for name in folders:
            found[os.path.relpath(os.path.join(root, name), folder)] = None
        for name in files:
            with open(os.path.join(root, name)) as file:
                found[os.path.relpath(os.path.join(root, name), folder)] = file.read()
    return found


def _interrupted_after(monkeypatch, n):
    """Patch os.mkdir, os.open and os.replace to raise KeyboardInterrupt right after the n-th call among them
    returned, unless formats.BEFORE_MOVES ran before (as the command line ignores stop signals then); returns the
    count of calls made so far (a one-element list)."""
    count, moving = [0], []

    def after(name, real):
        def call(*args, **kwargs):
            result = real(*args, **kwargs)
            count[0] += 1
            if count[0] == n and not moving:
                if name == "open":
                    os.close(result)
                raise KeyboardInterrupt
            return result
        return call

    for name in ("mkdir", "open", "replace"):
        monkeypatch.setattr(os, name, after(name, getattr(os, name)))
    monkeypatch.setattr(formats, "BEFORE_MOVES", [lambda: moving.append(True)])
    return count


def _write_results(base):
    outputs = [base / "made" / "deeper" / "R.csv", base / "old.csv"]
    with output_folders(outputs), replacing(*outputs) as temporaries:
        for temporary in temporaries:
            with open(temporary, "w") as file:
                file.write("new")


def _write_report(base):
    with output_folders([base / "rep"]), staged(base / "rep", folder=True) as folder, \
            staged(base / "out.FCStd") as fcstd:
        with open(os.path.join(folder, "index.html"), "w") as file:
            file.write("new")
        with open(fcstd, "w") as file:
            file.write("new")


def _fill(base):
    (base / "rep").mkdir()
    (base / "rep" / "index.html").write_text("an older report")
    (base / "old.csv").write_text("old")
    (base / "out.FCStd").write_text("old")


@pytest.mark.parametrize("write, written", [(_write_results, ["made/deeper/R.csv", "old.csv"]),
                                            (_write_report, ["rep/index.html", "out.FCStd"])],
                         ids=["results", "report"])
def test_a_stop_after_any_step_leaves_the_folder_as_it_was(tmp_path, monkeypatch, write, written):
    steps = 0
    for n in range(1, 40):
        base = tmp_path / str(n)
        base.mkdir()
        _fill(base)
        before = _listing(base)
        with monkeypatch.context() as patch:
            count = _interrupted_after(patch, n)
            try:
                write(base)
                interrupted = False
            except KeyboardInterrupt:
                interrupted = True
        if not interrupted:
            steps = count[0]
            break
        assert _listing(base) == before, f"interrupted after step {n}"
    assert steps >= 4, "every step was interrupted: the loop ended before the writing could finish"
    after = _listing(base)
    assert [after.get(name) for name in written] == ["new"] * len(written)
    assert not [name for name in after if os.path.basename(name).startswith(".")], after
