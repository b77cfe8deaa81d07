"""A zip archive of stored (uncompressed) members whose sizes are known up front, filled piece by piece.

Each member is reserved with its final size (:meth:`StoredZip.reserve`): its local header is written
and its bytes are set aside in the file at once, so that many members can then be filled side by side
(:meth:`StoredZip.append`, in order within each member) as data arrives, each byte written once, in
place. :meth:`StoredZip.close` checks that every member is full, writes each member's CRC-32 into its
local header, then the central directory. Members or offsets past 4 GiB get zip64 records; the
timestamps are fixed (1980-01-01 00:00), so the same members give the same bytes.

What the zip format says (PKWARE APPNOTE 6.3): a local header (30 bytes + name + extra) before each
member's bytes, a central directory of one 46-byte record (+ name + extra) per member, an end record.
Sizes and offsets in bytes.
"""

import os
import struct
import zlib

#: Sizes and offsets from this one on go in zip64 extra fields, their 32-bit fields holding _WIDE_MARK.
ZIP64_LIMIT = 0xFFFFFFFF
#: Member counts from this one on need the zip64 end records, the end record's 16-bit counts holding 0xFFFF.
ZIP64_COUNT = 0xFFFF
_WIDE_MARK = 0xFFFFFFFF
_LOCAL = struct.Struct("<4sHHHHHLLLHH")
_CENTRAL = struct.Struct("<4sHHHHHHLLLHHHHHLL")
_END = struct.Struct("<4sHHHHLLH")
_END64 = struct.Struct("<4sQHHLLQQQQ")
_LOCATOR64 = struct.Struct("<4sLQL")
#: Byte offset of the CRC-32 field in a local header.
_CRC_AT = 14
#: Versions needed to extract: 2.0 (plain), 4.5 (zip64); made by Unix (3).
_PLAIN, _WIDE, _UNIX = 20, 45, 3 << 8
#: DOS time and date of 1980-01-01 00:00.
_TIME, _DATE = 0, (1 << 5) | 1
#: Unix permissions rw-r--r-- of a regular file, as the central directory's external attributes.
_ATTRIBUTES = 0o100644 << 16


class Member:
    """A reserved member: its name (bytes), size, local header offset, data offset, bytes written so
    far and running CRC-32."""

    __slots__ = ("name", "size", "header", "data", "written", "crc")

    def __init__(self, name, size, header, data):
        self.name, self.size, self.header, self.data, self.written, self.crc = name, size, header, data, 0, 0


class StoredZip:
    """The zip file `path` (created or emptied), written as members are reserved and filled.

    Use as a context manager: the archive is completed (close) when the block ends normally, and the
    file just closed, incomplete, when it raises (its caller removes it, e.g. formats.replacing).
    """

    def __init__(self, path):
        # Emptied by ftruncate only when it is not empty already: on ext4, opening with O_TRUNC makes the
        # close wait for the data to be flushed (its auto_da_alloc), some 30 ms per 100 MB.
        self._fd = os.open(os.fspath(path), os.O_WRONLY | os.O_CREAT, 0o666)
        if os.fstat(self._fd).st_size:
            os.ftruncate(self._fd, 0)
        self._end, self.members = 0, []

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        if kind is None:
            self.close()
        else:
            self._release()
        return False

    def reserve(self, name, size):
        """A :class:`Member` `name` (str) of exactly `size` bytes, its local header written and its bytes
        set aside after the archive's last; ValueError for a name given twice or a negative size."""
        encoded = name.encode("utf-8")
        if any(member.name == encoded for member in self.members):
            raise ValueError(f"zip member {name!r} reserved twice")
        if size < 0:
            raise ValueError(f"zip member {name!r}: size {size} < 0")
        wide = size >= ZIP64_LIMIT
        extra = struct.pack("<HHQQ", 1, 16, size, size) if wide else b""
        stored = _WIDE_MARK if wide else size
        flags = 0 if encoded.isascii() else 0x800
        header = _LOCAL.pack(b"PK\x03\x04", _WIDE if wide else _PLAIN, flags, 0, _TIME, _DATE, 0, stored, stored,
                             len(encoded), len(extra)) + encoded + extra
        os.pwrite(self._fd, header, self._end)
        member = Member(encoded, size, self._end, self._end + len(header))
        self._end = member.data + size
        self.members.append(member)
        return member

    def append(self, member, data):
        """Write the bytes-like `data` (e.g. a contiguous numpy array) after `member`'s bytes so far;
        ValueError when it would overrun the member's reserved size."""
        view = memoryview(data).cast("B")
        if member.written + view.nbytes > member.size:
            raise ValueError(f"zip member {member.name.decode()!r}: {member.written + view.nbytes} bytes given, "
                             f"{member.size} reserved")
        done = 0
        while done < view.nbytes:
            done += os.pwrite(self._fd, view[done:], member.data + member.written + done)
        member.crc = zlib.crc32(view, member.crc)
        member.written += view.nbytes

    def add(self, name, data):
        """A member `name` holding the bytes-like `data` (reserve and append at once)."""
        self.append(self.reserve(name, memoryview(data).nbytes), data)

    def close(self):
        """Complete the archive: ValueError (the file left incomplete) if a member is not full; each CRC
        into its local header, then the central directory and the end records."""
        try:
            short = [member for member in self.members if member.written != member.size]
            if short:
                raise ValueError(f"zip member {short[0].name.decode()!r}: {short[0].written} of {short[0].size} "
                                 "bytes written")
            records = []
            for member in self.members:
                os.pwrite(self._fd, struct.pack("<L", member.crc), member.header + _CRC_AT)
                records.append(_central_record(member))
            directory = b"".join(records)
            os.pwrite(self._fd, directory + _end_records(len(self.members), len(directory), self._end),
                      self._end)
        finally:
            self._release()

    def _release(self):
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None


def _central_record(member):
    """The central directory record of a filled `member`."""
    wide_size, wide_offset = member.size >= ZIP64_LIMIT, member.header >= ZIP64_LIMIT
    fields = ([member.size, member.size] if wide_size else []) + ([member.header] if wide_offset else [])
    extra = struct.pack(f"<HH{len(fields)}Q", 1, 8 * len(fields), *fields) if fields else b""
    version = _WIDE if fields else _PLAIN
    size = _WIDE_MARK if wide_size else member.size
    return _CENTRAL.pack(b"PK\x01\x02", _UNIX | version, version, 0 if member.name.isascii() else 0x800, 0, _TIME,
                         _DATE, member.crc, size, size, len(member.name), len(extra), 0, 0, 0, _ATTRIBUTES,
                         _WIDE_MARK if wide_offset else member.header) + member.name + extra


def _end_records(count, size, offset):
    """The end records of a central directory of `count` records, `size` bytes at `offset`: the zip64
    end record and its locator first when any of them is too large for the plain end record."""
    if count < ZIP64_COUNT and size < ZIP64_LIMIT and offset < ZIP64_LIMIT:
        return _END.pack(b"PK\x05\x06", 0, 0, count, count, size, offset, 0)
    plain = _END.pack(b"PK\x05\x06", 0, 0, 0xFFFF, 0xFFFF, _WIDE_MARK, _WIDE_MARK, 0)
    wide = _END64.pack(b"PK\x06\x06", _END64.size - 12, _UNIX | _WIDE, _WIDE, 0, 0, count, count, size, offset)
    return wide + _LOCATOR64.pack(b"PK\x06\x07", 0, offset + size, 1) + plain
