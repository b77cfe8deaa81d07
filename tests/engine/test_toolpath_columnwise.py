"""The toolpath CSV read column by column: the same numbers, bit for bit, as parsing each field on its own
(the line-by-line reader, whose float() of each field in the strict grammar is the reference), and every
block it does not take left to the line-by-line reader, which names the bad line."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from abm_workbench.errors import InputError
from abm_workbench.formats import toolpath_csv
from abm_workbench.formats.toolpath_csv import _columnwise, _data_blocks, _line_by_line, load_table

HEADER = ["x", "y", "z", "i", "j", "k"]


def _data_lines(text):
    """(line number, line) of every data line of `text`, over all its blocks."""
    return [(int(number), line) for numbers, lines in _data_blocks(text) for number, line in zip(numbers, lines)]


def number_texts():
    """Numbers written as people and programs write them: repr, %.17g, %g, %e, integers, '.5', '5.',
    upper-case exponents, explicit signs, blanks around."""
    value = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)
    written = st.one_of(
        value.map(repr), value.map(lambda v: f"{v:.17g}"), value.map(lambda v: f"{v:g}"),
        value.map(lambda v: f"{v:E}"), st.integers(-10**6, 10**6).map(str),
        st.integers(0, 999).map(lambda n: f".{n}"), st.integers(0, 999).map(lambda n: f"+{n}."))
    return st.tuples(st.sampled_from(["", " ", "\t", "  "]), written, st.sampled_from(["", " ", "\t"])).map("".join)


@st.composite
def tables(draw):
    """The text of a toolpath CSV of only numbers, with comment and blank lines among its rows."""
    rows = draw(st.lists(st.lists(number_texts(), min_size=6, max_size=6), min_size=1, max_size=30))
    lines = [",".join(HEADER)]
    for row in rows:
        lines.extend(draw(st.lists(st.sampled_from(["", "# a comment", "   "]), max_size=1)))
        lines.append(",".join(row))
    return "\n".join(lines) + draw(st.sampled_from(["", "\n", "\r\n"]))


def by_lines(text):
    """The numbers of `text` by the line-by-line reader (the reference)."""
    lines = _data_lines(text)
    return _line_by_line("t.csv", HEADER, lines[1:])[0]


@given(tables())
def test_columns_are_the_line_by_line_readers_bit_for_bit(text):
    lines = [line for _, line in _data_lines(text)[1:]]
    found = _columnwise(HEADER, lines)
    assert found is not None
    expected = by_lines(text)
    assert list(found[0]) == list(expected)
    for column, values in expected.items():
        assert found[0][column].tobytes() == values.tobytes(), column


def test_the_line_numbers_skip_comments_and_blank_lines(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("# made by hand\nx,y,z,i,j,k\n\n1,2,3,0,0,1\n# between\n4,5,6,0,0,1\n")
    table = load_table(path)
    assert table.lines.tolist() == [4, 6] and table.numbers["y"].tolist() == [2.0, 5.0]


def test_empty_fields_where_allowed_are_nan(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("x,y,z,i,j,k,diameter,feed_rate\n1,2,3,0,0,1,,0.5\n1,2,3,0,0,1, 12 ,\n")
    lines = [line for _, line in _data_lines(path.read_text())[1:]]
    assert _columnwise(["x", "y", "z", "i", "j", "k", "diameter", "feed_rate"], lines) is not None
    table = load_table(path)
    assert np.array_equal(table.numbers["diameter"], [np.nan, 12.0], equal_nan=True)
    assert np.array_equal(table.numbers["feed_rate"], [0.5, np.nan], equal_nan=True)


# Fields the column-wise reader leaves to the line-by-line one, and what that one says (None: it reads it).
LEFT = {"١٣.٥": "not a number", "1_0.5": "not a number", "nan": "not a finite number", "inf": "not a finite number",
        "1e999": "too large", "2e12": "too large", "0x10": "not a number", "1e": "not a number", "--1": "not a number",
        "": "not a number", ".": "not a number", "1 2": "not a number", "1.5\u3000": None, '"1.5"': None}


@pytest.mark.parametrize("field", sorted(LEFT))
def test_what_it_does_not_take_the_line_by_line_reader_decides(tmp_path, field):
    rows = ["x,y,z,i,j,k"] + ["1,2,3,0,0,1"] * 5 + ["# note", f"1,{field},3,0,0,1", "1,2,3,0,0,1"]
    lines = rows[1:6] + rows[7:]
    assert _columnwise(HEADER, lines) is None
    path = tmp_path / "t.csv"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    if LEFT[field] is None:
        assert load_table(path).numbers["y"][5] == 1.5
    else:
        with pytest.raises(InputError, match=f"^{path}:8: column 'y': .*{LEFT[field]}"):
            load_table(path)


@pytest.mark.parametrize("line, message", [
    ("1,2,3,0,0", "expected 6 fields"), ("1,2,3,0,0,1,7", "expected 6 fields"),
    ("1,2,3,0,0," + "1" * (toolpath_csv.MAX_FIELD + 1), "a field of"),
])
def test_rows_of_the_wrong_shape_or_size_are_named(tmp_path, line, message):
    path = tmp_path / "t.csv"
    path.write_text("x,y,z,i,j,k\n1,2,3,0,0,1\n" + line + "\n")
    assert _columnwise(HEADER, ["1,2,3,0,0,1", line]) is None
    with pytest.raises(InputError, match=f"^{path}:3: {message}"):
        load_table(path)


@st.composite
def program_tables(draw):
    """The text of a toolpath command's CSV: text columns among the numbers, comments, blank lines."""
    header = ["operation", "name", "tool", "diameter", "x", "y", "z", "i", "j", "k", "feed_rate", "feed_unit", "line"]
    lines = [",".join(header)]
    for _ in range(draw(st.integers(1, 25))):
        lines.extend(draw(st.lists(st.sampled_from(["", "# a comment"]), max_size=1)))
        name = draw(st.sampled_from(["Pocket 1", " Contour", "Adaptive-2 ", "", "ÄÖ roughing"]))
        tool = draw(st.sampled_from(["flat", "ball", "bull", ""]))
        numbers = draw(st.lists(number_texts(), min_size=6, max_size=6))
        feed, unit = draw(st.sampled_from([("", ""), ("1200", "MMPM"), (" 0.1", "MMPR")]))
        diameter = draw(st.sampled_from(["", "6", " 12.5"]))
        lines.append(",".join([str(draw(st.integers(1, 3))), name, tool, diameter, *numbers, feed, unit,
                               str(draw(st.integers(0, 10**6)))]))
    return header, "\n".join(lines) + "\n"


@given(program_tables())
def test_text_columns_are_read_column_by_column_as_line_by_line(case):
    header, text = case
    lines = _data_lines(text)[1:]
    found = _columnwise(header, [line for _, line in lines])
    assert found is not None
    numbers, texts = _line_by_line("t.csv", header, lines)
    assert list(found[0]) == list(numbers) and found[1] == texts
    for column, values in numbers.items():
        assert found[0][column].tobytes() == values.tobytes(), column


def _rows(count, bad=None):
    """A toolpath CSV's text of `count` rows with comments now and then; row `bad` (0-based) has a word."""
    lines = ["# written by a test", "x,y,z,i,j,k"]
    for n in range(count):
        if n % 97 == 0:
            lines.append("# level")
        y = "here" if n == bad else f"{n * 0.1:.3f}"
        lines.append(f"{n % 80},{y},-{n % 7}.5,0,0,1")
    return "\n".join(lines) + "\n"


def test_blocks_give_the_whole_files_table_and_line_numbers(tmp_path, monkeypatch):
    path = tmp_path / "t.csv"
    path.write_text(_rows(5000))
    whole = load_table(path)
    monkeypatch.setattr(toolpath_csv, "BLOCK_CHARS", 1000)
    blocks = load_table(path)
    assert sum(1 for _ in _data_blocks(path.read_text())) > 50
    assert blocks.lines.tobytes() == whole.lines.tobytes() and whole.lines[-1] == len(path.read_text().splitlines())
    for column in HEADER:
        assert blocks.numbers[column].tobytes() == whole.numbers[column].tobytes(), column


def test_a_bad_row_in_a_later_block_is_named_by_its_line(tmp_path, monkeypatch):
    monkeypatch.setattr(toolpath_csv, "BLOCK_CHARS", 1000)
    path = tmp_path / "t.csv"
    path.write_text(_rows(3000, bad=2500))
    line = 1 + path.read_text().splitlines().index("20,here,-1.5,0,0,1")
    with pytest.raises(InputError, match=f"^{path}:{line}: column 'y': .*not a number"):
        load_table(path)


def test_a_long_file_is_read_in_a_few_times_its_size(tmp_path, monkeypatch):
    """The reader's working memory stays a small multiple of the file (the whole text in one list of fields
    took some 40 times the file's size)."""
    import tracemalloc
    monkeypatch.setattr(toolpath_csv, "BLOCK_CHARS", 1 << 16)
    path = tmp_path / "t.csv"
    path.write_text(_rows(100_000))
    size = path.stat().st_size
    tracemalloc.start()
    try:
        table = load_table(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert len(table.lines) == 100_000
    assert peak < 12 * size, f"peak {peak / size:.1f} x the file's {size:,} bytes"
