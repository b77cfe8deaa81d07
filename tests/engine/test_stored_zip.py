"""formats.stored_zip: members reserved and filled side by side read back by Python's zipfile and numpy's
npz reader (independent readers, CRCs checked), zip64 records where sizes or offsets need them, and
misuse refused."""

import io
import shutil
import subprocess
import zipfile

import numpy as np
import pytest

from abm_workbench.formats import stored_zip
from abm_workbench.formats.stored_zip import StoredZip


def npy_bytes(array):
    """The .npy file of `array` by numpy's own writer."""
    data = io.BytesIO()
    np.save(data, array, allow_pickle=False)
    return data.getvalue()


def interleaved(path, arrays, pieces=5):
    """Write `arrays` (name -> array) as .npy members of `path`, each reserved first and then filled
    `pieces` pieces at a time, the members taking turns (as chunks of a pass arrive)."""
    files = {name: npy_bytes(array) for name, array in arrays.items()}
    with StoredZip(path) as archive:
        members = {name: archive.reserve(name + ".npy", len(data)) for name, data in files.items()}
        cuts = {name: np.linspace(0, len(data), pieces + 1).astype(int) for name, data in files.items()}
        for k in range(pieces):
            for name, data in files.items():
                archive.append(members[name], np.frombuffer(data[cuts[name][k]:cuts[name][k + 1]], np.uint8))
    return files


ARRAYS = {"length": np.linspace(-1.0, 2.0, 1001), "cl": np.arange(777, dtype=np.int64),
          "case": np.arange(300, dtype=np.uint8) % 7, "empty": np.zeros(0), "labels/case": np.array(["a", "bc"])}


def test_members_filled_side_by_side_read_back_by_zipfile_and_numpy(tmp_path):
    path = tmp_path / "a.npz"
    files = interleaved(path, ARRAYS)
    with zipfile.ZipFile(path) as archive:
        assert archive.testzip() is None  # every CRC checked
        assert [info.filename for info in archive.infolist()] == [name + ".npy" for name in ARRAYS]
        assert {info.compress_type for info in archive.infolist()} == {zipfile.ZIP_STORED}
        for name, data in files.items():
            assert archive.read(name + ".npy") == data
    with np.load(path, allow_pickle=False) as archive:
        assert archive.files == list(ARRAYS)
        for name, array in ARRAYS.items():
            assert archive[name].dtype == array.dtype and np.array_equal(archive[name], array), name


def test_the_same_members_give_the_same_bytes(tmp_path):
    interleaved(tmp_path / "a.npz", ARRAYS, pieces=3)
    interleaved(tmp_path / "b.npz", ARRAYS, pieces=7)
    assert (tmp_path / "a.npz").read_bytes() == (tmp_path / "b.npz").read_bytes()


@pytest.mark.parametrize("limit, count", [(64, 1 << 16), (1 << 40, 3)])
def test_zip64_records_where_sizes_offsets_or_the_count_need_them(tmp_path, monkeypatch, limit, count):
    """Limits lowered so that small members take the zip64 paths that members past 4 GiB (or 65,535
    members) take: zipfile and numpy still read every member and its size, and the zip64 records are there."""
    monkeypatch.setattr(stored_zip, "ZIP64_LIMIT", limit)
    monkeypatch.setattr(stored_zip, "ZIP64_COUNT", count)
    path = tmp_path / "wide.npz"
    files = interleaved(path, ARRAYS)
    data = path.read_bytes()
    assert b"PK\x06\x06" in data and b"PK\x06\x07" in data
    with zipfile.ZipFile(path) as archive:
        assert archive.testzip() is None
        assert {info.filename: info.file_size for info in archive.infolist()} == {
            name + ".npy": len(content) for name, content in files.items()}
    with np.load(path, allow_pickle=False) as archive:
        for name, array in ARRAYS.items():
            assert np.array_equal(archive[name], array), name


def test_plain_archives_have_no_zip64_records(tmp_path):
    interleaved(tmp_path / "a.npz", ARRAYS)
    data = (tmp_path / "a.npz").read_bytes()
    assert b"PK\x06\x06" not in data and b"\x01\x00\x10\x00" not in data


def test_misuse_is_refused(tmp_path):
    with StoredZip(tmp_path / "a.zip") as archive:
        member = archive.reserve("a", 4)
        with pytest.raises(ValueError, match="5 bytes given, 4 reserved"):
            archive.append(member, b"12345")
        with pytest.raises(ValueError, match="reserved twice"):
            archive.reserve("a", 1)
        with pytest.raises(ValueError, match="size -1"):
            archive.reserve("b", -1)
        archive.append(member, b"1234")
    with pytest.raises(ValueError, match="'short': 2 of 3 bytes written"):
        with StoredZip(tmp_path / "b.zip") as archive:
            archive.append(archive.reserve("short", 3), b"12")


def test_a_block_that_raises_leaves_the_file_incomplete_and_closed(tmp_path):
    path = tmp_path / "a.zip"
    with pytest.raises(KeyboardInterrupt):
        with StoredZip(path) as archive:
            archive.add("a", b"abc")
            raise KeyboardInterrupt
    assert not zipfile.is_zipfile(path)


def test_non_ascii_names_are_flagged_utf8(tmp_path):
    path = tmp_path / "a.zip"
    with StoredZip(path) as archive:
        archive.add("φ.txt", "π".encode())
    with zipfile.ZipFile(path) as archive:
        assert archive.namelist() == ["φ.txt"] and archive.read("φ.txt") == "π".encode()


@pytest.mark.skipif(shutil.which("unzip") is None, reason="Info-ZIP's unzip is not installed")
@pytest.mark.parametrize("limit", [64, stored_zip.ZIP64_LIMIT])
def test_info_zip_reads_it_too(tmp_path, monkeypatch, limit):
    monkeypatch.setattr(stored_zip, "ZIP64_LIMIT", limit)
    interleaved(tmp_path / "a.zip", ARRAYS)
    done = subprocess.run(["unzip", "-t", str(tmp_path / "a.zip")], capture_output=True, text=True)
    assert done.returncode == 0 and "No errors detected" in done.stdout, done.stdout + done.stderr
