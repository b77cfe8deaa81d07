"""The GUI tier's harness (conftest.run_macro): a FreeCAD that crashes in the middle of a macro fails the
test with what it left (its exit status, that the macro had started, the Python stack of the crash),
not with a bare "no verdict"."""

import pytest

from tests.gui.conftest import run_macro

CRASH = """
import os, signal
def crash_here():
    verdict["before"] = True
    os.kill(os.getpid(), signal.SIGSEGV)
crash_here()
"""


def test_a_crash_in_the_macro_is_told_with_its_signal_and_stack(tmp_path):
    with pytest.raises(pytest.fail.Exception) as failure:
        run_macro(CRASH, tmp_path)
    told = str(failure.value)
    assert "ended after the macro started, before its verdict" in told, told
    # FreeCAD's own handler prints the signal and C++ stack and exits with status 1; faulthandler the Python stack
    assert "exit status 1" in told and "Program received signal SIGSEGV" in told, told
    assert "Fatal Python error: Segmentation fault" in told and "in crash_here" in told, told
