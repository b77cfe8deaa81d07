"""Feeds written back in each CAM system's own FEDRAT form.

Each CL text below is shaped like its CAM system's output. One operation gets new feeds; the
result must keep every original line, write every inserted FEDRAT in the dialect's pattern,
read back through this project's reader and through an independent reader that follows the
dialect's own rule (SOLIDWORKS CAM: the first field after '/' is the feed; NX and Mastercam:
the number after the unit word; ...) to the scheduled feeds rounded down at the file's decimals.
"""

import re
from typing import Callable, NamedTuple

import numpy as np
import pytest

from abm_workbench.formats.cl import read_program
from abm_workbench.formats.cl.rewrite import rewritten_text

from .test_cl_rewrite import without_inserted

#: Scheduled feeds (mm/min), given in turn to the moves of the operation: a limit computed by a
#: schedule, integers, a value a decimal step away in inches (185.42 mm/min = 7.3 in/min).
SCHEDULED = (873.2212826059239, 600.0, 512.5, 185.42, 333.3333333333333)
INCH = 25.4
_LEADING_NUMBER = re.compile(r"\s*[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)")


def fields_of(line):
    """The fields after '/' of a FEDRAT line (any case, blanks dropped), or None for another line."""
    head, slash, rest = line.partition("$$")[0].partition("/")
    if not slash or head.strip().upper() != "FEDRAT":
        return None
    fields = [field.strip() for field in rest.split(",")]
    return fields[:-1] if fields[-1] == "" else fields


def atof(text):
    """C's atof: the number `text` starts with, 0 when it starts with none."""
    match = _LEADING_NUMBER.match(text)
    return float(match.group()) if match else 0.0


def per_unit(word):
    """mm per length unit of the feed unit word `word` (MMPM, IPM, ... in any case)."""
    return INCH if word.upper().startswith("I") else 1.0


def first_field_is_the_feed(fields):
    """SOLIDWORKS CAM's post, Creo, CATIA, PowerMill: FEDRAT/f,unit; a unit-first record reads as feed 0."""
    return atof(fields[0]) * per_unit(fields[1])


def number_after_the_unit(fields):
    """NX, Mastercam: FEDRAT/unit,f; a value-first record is refused."""
    assert fields[0].upper() in ("MMPM", "IPM", "MMPR", "IPR"), fields
    return float(fields[1]) * per_unit(fields[0])


def bare_inch(fields):
    """A file in inches writing FEDRAT/f: the number is inches per minute."""
    assert len(fields) == 1, fields
    return float(fields[0]) * INCH


class Dialect(NamedTuple):
    text: str                  # the CL file
    operation: int             # the operation given new feeds
    pattern: str               # every inserted FEDRAT matches it
    read: Callable             # the dialect's own FEDRAT rule: fields -> mm/min (or mm/rev)
    decimals: int              # the decimals written
    scale: float = 1.0         # mm per the file's length unit
    feed_scale: float = 1.0    # SCHEDULED times this: the feeds given (1e-4: per revolution)


SOLIDWORKS = """\
PARTNO/BRACKET
$$ SOLIDWORKS CAM APT CL
UNIT/MM
CUTTER/14.,0,7.,0,0,0,84.
LOAD/TOOL,5
CSI_SET_FLUTE_LENGTH/32.
SPINDL/2321,RPM,CLW
COOLNT/ON
RAPID
GOTO/0,0,25.
FEDRAT/801.963285,MMPM
GOTO/0,0,-25.75
GOTO/57.,0,-25.75
CIRCLE/57.,57.,-25.75,0,0,1.
GOTO/114.,57.,-25.75
GOTO/114.,114.,-25.75
RAPID
GOTO/114.,114.,25.
CUTTER/10.,0,5.,0,0,0,72.
LOAD/TOOL,6
CSI_SET_FLUTE_LENGTH/22.
SPINDL/3183,RPM,CLW
RAPID
GOTO/20.,20.,25.
GOTO/20.,20.,-10.5
GOTO/60.,20.,-10.5
FEDRAT/889.,MMPM
GOTO/60.,60.,-10.5
COOLNT/OFF
END
"""

INCH_IPM = """\
PARTNO/BOSS
$$ APT CL in inches, unit first (as tests/fixtures/cl/solidworks_cam_inch.clt)
UNITS/INCHES
CUTTER/0.5,0.,0.,0.,0.,0.,2.
CSI_SET_FLUTE_LENGTH/1.25
LOADTL/3
SPINDL/SFM,400.,CLW
RAPID
GOTO/1.,0.,0.5
FEDRAT/IPM,30.
GOTO/1.,0.,-0.1
CIRCLE/0.,0.,-0.1,0.,0.,1.
GOTO/0.,1.,-0.1
GOTO/0.,2.,-0.1
GOTO/1.5,2.,-0.1
CUTTER/0.25,0.,0.,0.,0.,0.,1.5
LOADTL/4
RAPID
GOTO/0.,2.,0.5
GOTO/0.,2.,-0.2
GOTO/1.,2.,-0.2
END
"""

CREO = """\
$$* Pro/CLfile Version Creo 9.0 - M030
$$-> MFGNO / PLATE
PARTNO / PLATE
$$-> FEATNO / 45
MACHIN / UNCX01, 1
$$-> CUTCOM_GEOMETRY_TYPE / OUTPUT_ON_CENTER
UNITS / MM
LOADTL / 1
$$-> CUTTER / 10.000000
SPINDL / RPM, 3000.000000, CLW
RAPID
GOTO / 0.0000000000, 0.0000000000, 10.0000000000
FEDRAT / 500.000000, MMPM
GOTO / 0.0000000000, 0.0000000000, -1.0000000000
GOTO / 20.0000000000, 0.0000000000, -1.0000000000
CIRCLE / 20.0000000000, 10.0000000000, -1.0000000000, 0.0000000000, 0.0000000000, 1.0000000000, 10.0000000000
GOTO / 30.0000000000, 10.0000000000, -1.0000000000
GOTO / 30.0000000000, 30.0000000000, -1.0000000000
RAPID
GOTO / 30.0000000000, 30.0000000000, 10.0000000000
$$-> END /
$$-> FEATNO / 52
LOADTL / 2
$$-> CUTTER / 6.000000
SPINDL / RPM, 8000.000000, CLW
RAPID
GOTO / 40.0000000000, 0.0000000000, 10.0000000000
GOTO / 40.0000000000, 0.0000000000, -3.0000000000
GOTO / 50.0000000000, 0.0000000000, -3.0000000000
$$-> END /
FINI
"""

CATIA = """\
$$ -----------------------------------------------------------------
$$ Generated on Monday, March 04, 2024 10:12:31 AM
$$ -----------------------------------------------------------------
$$ Manufacturing Program.1
PARTNO PART1
$$*CATIA0
$$ Part Operation.1
multax
$$ OPERATION NAME : Pocketing.1
$$ Start generation of : Pocketing.1
tprint/ T1 End Mill D 8
loadtl/ 1, adjust, 1, mill
cutter/ 8.000000, 0.000000, 4.000000, 0.000000, 0.000000, 0.000000, 50.000000
spindl/ 5000.0000, rpm, clw
tlaxis/ 0.000000, 0.000000, 1.000000
rapid
goto  / 0.00000, 0.00000, 30.00000
fedrat/ 600.0000, mmpm
goto  / 0.00000, 0.00000, -2.00000
goto  / 15.00000, 0.00000, -2.00000
goto  / 15.00000, 10.00000, -2.00000
goto  / 0.00000, 10.00000, -2.00000
goto  / 0.00000, 20.00000, -2.00000
$$ End of generation of : Pocketing.1
$$ OPERATION NAME : Profile Contouring.2
$$ Start generation of : Profile Contouring.2
rapid
goto  / 30.00000, 0.00000, 30.00000
goto  / 30.00000, 0.00000, -4.00000
goto  / 30.00000, 20.00000, -4.00000
$$ End of generation of : Profile Contouring.2
stop
"""

NX = """\
TOOL PATH/CAVITY_MILL,TOOL,EM10
TLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000
MSYS/0.0000,0.0000,0.0000,1.0000000,0.0000000,0.0000000,0.0000000,1.0000000,0.0000000
$$ centerline data
PAINT/PATH
PAINT/SPEED,10
LOAD/TOOL,1
SPINDL/RPM,6000,CLW
PAINT/COLOR,186
RAPID
GOTO/0.0000,0.0000,20.0000,0.0000000,0.0000000,1.0000000
PAINT/COLOR,42
FEDRAT/MMPM,400.0000
GOTO/0.0000,0.0000,5.0000
GOTO/20.0000,0.0000,5.0000
CIRCLE/20.0000,10.0000,5.0000,0.0000000,0.0000000,1.0000000,10.0000,0.0600,0.5000,10.0000,0.0000
GOTO/30.0000,10.0000,5.0000
GOTO/30.0000,30.0000,5.0000
PAINT/SPEED,10
END-OF-PATH
TOOL PATH/FLOOR_FINISH,TOOL,EM10
TLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000
LOAD/TOOL,1
PAINT/COLOR,186
RAPID
GOTO/50.0000,0.0000,20.0000
GOTO/50.0000,0.0000,2.0000
GOTO/60.0000,0.0000,2.0000
END-OF-PATH
"""

MASTERCAM = """\
PARTNO/MC TEST,
UNIT/MM
$$ Mastercam APT
LOADTL/1,MILL
CUTTER/12.,0.,6.,0.,0.,0.,60.,
SPINDL/RPM,3000.,CLW,
RAPID/
GOTO/30.,0.,25.,
FEDRAT/MMPM,900.,
GOTO/30.,0.,0.,
CIRCLE/0.,0.,0.,0.,0.,1.,30.,
GOTO/0.,30.,0.,
GOTO/0.,40.,-2.,
GOTO/10.,40.,-2.,
RAPID/
GOTO/10.,40.,25.,
LOADTL/2,MILL
CUTTER/8.,0.,4.,0.,0.,0.,50.,
SPINDL/RPM,4000.,CLW,
RAPID/
GOTO/50.,0.,25.,
GOTO/50.,0.,-1.5,
GOTO/60.,0.,-1.5,
END
"""

POWERMILL = """\
$$ PowerMill APT
PARTNO/SHAFT
MULTAX/ON
LOADTL/4
CUTTER/10.0,0.0,5.0,0.0,0.0,0.0,40.0
SPINDL/4000,RPM,CLW
$$ Toolpath: FACE
TLAXIS/0.0,0.0,1.0
RAPID
GOTO/0.0,0.0,60.0
FEDRAT/1200.0,MMPM
GOTO/0.0,0.0,20.0
GOTO/30.0,0.0,20.0
GOTO/30.0,20.0,20.0
GOTO/0.0,20.0,20.0
GOTO/0.0,40.0,20.0
LOADTL/5
CUTTER/6.0,0.0,3.0,0.0,0.0,0.0,30.0
RAPID
GOTO/0.0,0.0,60.0
GOTO/0.0,0.0,25.0
GOTO/30.0,0.0,25.0
END
"""

BARE_INCH = """\
PARTNO/GENERIC APT
UNITS/INCHES
CUTTER/0.5
LOADTL/1
SPINDL/1800,CLW
RAPID
GOTO/0.0,0.0,1.0
FEDRAT/20.0
GOTO/0.0,0.0,-0.1
GOTO/2.0,0.0,-0.1
GOTO/2.0,1.0,-0.1
GOTO/0.0,1.0,-0.1
GOTO/0.0,2.0,-0.1
LOADTL/2
CUTTER/0.25
RAPID
GOTO/3.0,0.0,1.0
GOTO/3.0,0.0,-0.2
GOTO/4.0,0.0,-0.2
FINI
"""

INCH_PER_REV = """\
UNITS/INCHES
CUTTER/0.375
LOADTL/7,MILL
SPINDL/RPM,2500,CLW
RAPID
GOTO/0,0,1
FEDRAT/.004,IPR
GOTO/0,0,-.25
GOTO/1.5,0,-.25
GOTO/1.5,.75,-.25
GOTO/0,.75,-.25
GOTO/0,1.5,-.25
LOADTL/8,MILL
CUTTER/.25
GOTO/2,0,1
GOTO/2,0,-.125
END
"""

COMPACT = r"(?:[0-9]+\.|[0-9]+\.[0-9]*[1-9])"   # an integer with its '.', else no trailing zeros
DIALECTS = {
    "solidworks-cam": Dialect(SOLIDWORKS, 1, rf"FEDRAT/{COMPACT},MMPM", first_field_is_the_feed, 6),
    "inch-ipm": Dialect(INCH_IPM, 1, rf"FEDRAT/IPM,{COMPACT}", number_after_the_unit, 6, INCH),
    "creo": Dialect(CREO, 1, r"FEDRAT / [0-9]+\.[0-9]{6}, MMPM", first_field_is_the_feed, 6),
    "catia-v5": Dialect(CATIA, 1, r"fedrat/ [0-9]+\.[0-9]{4}, mmpm", first_field_is_the_feed, 4),
    "nx-clsf": Dialect(NX, 1, r"FEDRAT/MMPM,[0-9]+\.[0-9]{4}", number_after_the_unit, 4),
    "mastercam": Dialect(MASTERCAM, 1, rf"FEDRAT/MMPM,{COMPACT},", number_after_the_unit, 6),
    "powermill": Dialect(POWERMILL, 1, r"FEDRAT/[0-9]+\.[0-9],MMPM", first_field_is_the_feed, 1),
    "bare-inch": Dialect(BARE_INCH, 1, r"FEDRAT/[0-9]+\.[0-9]", bare_inch, 1, INCH),
    "inch-per-rev": Dialect(INCH_PER_REV, 1, r"FEDRAT/\.[0-9]*[1-9],IPR", first_field_is_the_feed, 6, INCH, 1e-4),
}


def scheduled_feeds(op, feed_scale):
    """The feeds given to `op`'s cutting points: SCHEDULED in turn by move, an arc's points each a
    little lower than the one before (the lowest is written)."""
    moves = list(dict.fromkeys(op.lines.tolist()))
    feed = np.array([SCHEDULED[moves.index(line) % len(SCHEDULED)] for line in op.lines.tolist()]) * feed_scale
    for line in moves:
        at = op.lines == line
        feed[at] -= np.arange(at.sum()) * 1e-3 * feed_scale
    return feed


def independent_feeds(text, read):
    """{line: feed in force} at each GOTO of `text` (1-based lines), FEDRATs read by `read`."""
    feeds, feed = {}, None
    for number, line in enumerate(text.splitlines(), start=1):
        fields = fields_of(line)
        if fields is not None:
            feed = read(fields)
        elif line.strip().upper().startswith("GOTO"):
            feeds[number] = feed
    return feeds


def program_of(folder, text, name="cl.apt"):
    """read_program of `text` written to `folder`/`name` as it is (line ends kept)."""
    path = folder / name
    path.write_bytes(text.encode())
    return read_program(path)


def check_read_back(dialect, program, again, text, feed):
    """`text` (`program` rewritten, read back as `again`) read by the dialect's own rule and by
    read_program gives, at every cutting point of the operation, `feed` rounded down at the
    dialect's decimals (within one step of the last decimal, never above), and the other
    operations' feeds as before."""
    op, new = program.operation(dialect.operation), again.operation(dialect.operation)
    own = independent_feeds(text, dialect.read)
    got = np.array([own[line] for line in new.lines.tolist()])
    np.testing.assert_array_equal(new.feed, got)
    lowest = {line: feed[op.lines == line].min() for line in op.lines.tolist()}
    wanted = np.array([lowest[line] for line in op.lines.tolist()])
    step = 10.0 ** -dialect.decimals * dialect.scale
    assert (got > 0).all()
    assert (got <= wanted * (1 + 1e-15)).all()
    assert (wanted - got < step * (1 + 1e-9)).all()
    for before, after in zip(program.operations, again.operations):
        if before.number != dialect.operation:
            np.testing.assert_array_equal(after.feed, before.feed)
            np.testing.assert_array_equal(after.feed, [own[line] for line in after.lines.tolist()])


@pytest.mark.parametrize("name", DIALECTS)
def test_inserted_feeds_are_written_and_read_as_the_dialect_does(tmp_path, name):
    dialect = DIALECTS[name]
    program = program_of(tmp_path, dialect.text)
    assert not program.warnings and not program.unknown
    assert len(program.operations) == 2
    feed = scheduled_feeds(program.operation(dialect.operation), dialect.feed_scale)
    text = rewritten_text(program, dialect.operation, feed)
    kept, inserted = without_inserted(text, program.text)
    assert kept == program.text
    assert len(inserted) >= 4   # a new feed per move and the feed in force put back after
    for line in inserted:
        assert re.fullmatch(dialect.pattern, line.rstrip("\n")), line
    check_read_back(dialect, program, program_of(tmp_path, text, "out.apt"), text, feed)


def test_the_old_unit_first_form_fails_the_solidworks_cam_reader(tmp_path):
    dialect = DIALECTS["solidworks-cam"]
    program = program_of(tmp_path, dialect.text)
    feed = scheduled_feeds(program.operation(1), 1.0)
    text = rewritten_text(program, 1, feed)
    _, inserted = without_inserted(text, program.text)
    old = text
    for line in inserted:
        old = old.replace(line, f"FEDRAT/MMPM,{float(fields_of(line)[0])!r}\n")
    assert first_field_is_the_feed(fields_of("FEDRAT/MMPM,873.2212826059239")) == 0.0
    assert 0.0 in independent_feeds(old, first_field_is_the_feed).values()
    with pytest.raises(AssertionError):
        check_read_back(dialect, program, program_of(tmp_path, old, "old.apt"), old, feed)
