"""Whatever CL-like text a file holds, read_program gives a Program or an InputError, never
another exception (the command line turns InputError into exit status 2)."""

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program

WORDS = ["GOTO", "CIRCLE", "NURBS", "KNOT", "CNTRL", "RAPID", "FEDRAT", "SPINDL", "CUTTER", "TLDATA", "LOADTL",
         "UNITS", "UNIT", "MSYS", "CSYS", "ROTABL", "CYCLE", "TLAXIS", "GODLTA", "FROM", "MULTAX", "TOOL PATH",
         "PPRINT", "CSI_SET_FLUTE_LENGTH", "LOAD", "PAINT", "END-OF-PATH", "$$->CUTTER", "$$ OPERATION NAME :"]
ARGS = st.one_of(st.floats(-1e3, 1e3, allow_nan=False).map(lambda v: f"{v:.4f}"), st.sampled_from(
    ["", "0", "1", "-1", "MM", "INCH", "INCHES", "MMPM", "IPR", "SFM", "RPM", "CLW", "OFF", "ON", "DRILL", "TURN",
     "MILL", "BAXIS", "INCR", "TOOL", "CNTRL/1", "x", "1e999", "$"]))


@st.composite
def records(draw):
    word = draw(st.sampled_from(WORDS))
    args = draw(st.lists(ARGS, max_size=13))
    separator = " " if word.startswith("$$") else "/"
    return word + separator + ",".join(args)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(records(), min_size=1, max_size=25))
def test_any_record_sequence_reads_or_raises_input_error(tmp_path, lines):
    path = tmp_path / "fuzz.cl"
    path.write_text("\n".join(lines) + "\n")
    try:
        program = read_program(path)
    except InputError:
        return
    for op in program.operations:
        op.refusal()
        try:
            op.toolpath()
        except InputError:
            pass
