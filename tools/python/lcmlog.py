"""lcmlog - read and write LCM log files (the lcm-logger format) in pure Python.

No liblcm and no LCM Python binding needed (Debian 12 has none). The format,
as LCM documents it (all integers big-endian), one record per message:

    uint32 sync 0xEDA1DA01, int64 event number, int64 timestamp (us),
    int32 channel length, int32 data length, channel bytes, data bytes

The reader keeps the rules of trk's C reader (tools/lcm/lcm_log.c): a corrupt
header (channel length outside 1..999, negative data length) is skipped by
resynchronising on the next sync word, the bytes skipped are counted, a file
that ends inside a record is reported as truncated (not an error), a message
larger than max_data is skipped (its data is None), and a file without one
complete record, or max_resync bytes without a valid record, is an error.
Memory stays bounded: the file is read in chunks.

    import lcmlog
    for ev in lcmlog.LogReader("tracks.lcmlog"):
        print(ev.eventnum, ev.timestamp, ev.channel, len(ev.data))

A channel name is returned as str (UTF-8, undecodable bytes kept by
surrogateescape); a NUL inside it is kept, so "TRK_TRACKS\\0x" is not
"TRK_TRACKS".

Python standard library only.
"""

import struct
from collections import namedtuple

__all__ = ["SYNC", "MAX_CHANNEL", "MAX_RESYNC", "Event", "LogError", "LogReader", "LogWriter", "read_events"]

SYNC = 0xEDA1DA01
MAX_CHANNEL = 999          # liblcm's limit for channel names in logs
MAX_RESYNC = 64 << 20      # bytes one resynchronisation may skip
_SYNC_BYTES = struct.pack(">I", SYNC)
_HEADER = struct.Struct(">Iqqii")   # 28 bytes
_CHUNK = 1 << 16

Event = namedtuple("Event", "eventnum timestamp channel data")
Event.__doc__ = """One log record: eventnum (int), timestamp (int, microseconds; lcm-logger's
receive time, trk's replay: the scan time), channel (str), data (bytes, or None
when it was larger than the reader's max_data)."""


class LogError(Exception):
    """The file is no LCM log, or no record was found within the
    resynchronisation bound, or it cannot be read."""


class LogReader:
    """Iterate over the events of an LCM log file (a path or a binary file
    object). After (or during) the iteration: n_events, n_corrupt (corrupt
    headers skipped), n_bytes_skipped (while resynchronising), truncated
    (the file ended inside a record)."""

    def __init__(self, source, max_data=64 << 20, max_resync=MAX_RESYNC):
        self._own = not hasattr(source, "read")
        try:
            self._f = open(source, "rb") if self._own else source
        except OSError as e:
            raise LogError("%s: %s" % (source, e.strerror or e)) from e
        self.name = source if self._own else getattr(source, "name", "<stream>")
        self.max_data = max_data
        self.max_resync = max_resync
        self.n_events = 0
        self.n_corrupt = 0
        self.n_bytes_skipped = 0
        self.truncated = False
        self._buf = b""
        self._pos = 0
        self._eof = False
        self._nonempty = False

    def close(self):
        if self._own:
            self._f.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _fill(self, n):
        """At least n bytes from _pos in _buf, unless the file ends: True if so."""
        while len(self._buf) - self._pos < n and not self._eof:
            chunk = self._f.read(max(_CHUNK, n))
            if not chunk:
                self._eof = True
                break
            self._nonempty = True
            self._buf = self._buf[self._pos:] + chunk
            self._pos = 0
        return len(self._buf) - self._pos >= n

    def _take(self, n):
        b = self._buf[self._pos:self._pos + n]
        self._pos += n
        return b

    def _skip(self, n):
        """Skip n bytes (possibly beyond the buffer): True, or False at the end."""
        have = len(self._buf) - self._pos
        if n <= have:
            self._pos += n
            return True
        n -= have
        self._buf, self._pos = b"", 0
        while n > 0:
            chunk = self._f.read(min(n, 1 << 20))
            if not chunk:
                self._eof = True
                return False
            n -= len(chunk)
        return True

    def _sync(self):
        """Move to the next sync word: True found, False end of file."""
        gap = 0
        while True:
            if not self._fill(4):
                rest = len(self._buf) - self._pos
                if rest:
                    self.n_bytes_skipped += rest
                    self.truncated = True
                    self._pos = len(self._buf)
                return False
            i = self._buf.find(_SYNC_BYTES, self._pos)
            if i >= 0:
                self.n_bytes_skipped += i - self._pos
                gap += i - self._pos
                self._pos = i
                if gap > self.max_resync:
                    raise LogError("%s: no LCM log record found within the resynchronisation bound" % self.name)
                return True
            # keep the last 3 bytes: a sync word may straddle two chunks
            keep = max(len(self._buf) - 3, self._pos)
            self.n_bytes_skipped += keep - self._pos
            gap += keep - self._pos
            self._pos = keep
            if gap > self.max_resync:
                raise LogError("%s: no LCM log record found within the resynchronisation bound" % self.name)
            if self._eof:
                continue
            self._fill(len(self._buf) - self._pos + _CHUNK)

    def _end(self):
        if self.n_events == 0 and self._nonempty:
            raise LogError("%s: not an LCM log (no complete record)" % self.name)

    def __iter__(self):
        try:
            while True:
                if not self._sync():
                    self._end()
                    return
                if not self._fill(_HEADER.size):
                    self.truncated = True
                    self._end()
                    return
                _, eventnum, timestamp, chlen, dlen = _HEADER.unpack_from(self._buf, self._pos)
                if chlen <= 0 or chlen > MAX_CHANNEL or dlen < 0:
                    # corrupt header: resynchronise just after this sync word
                    self.n_corrupt += 1
                    self._pos += 4
                    continue
                self._pos += _HEADER.size
                if not self._fill(chlen):
                    self.truncated = True
                    self._end()
                    return
                channel = self._take(chlen).decode("utf-8", "surrogateescape")
                if dlen > self.max_data:
                    if not self._skip(dlen):
                        self.truncated = True
                        self._end()
                        return
                    data = None
                else:
                    if not self._fill(dlen):
                        self.truncated = True
                        self._end()
                        return
                    data = self._take(dlen)
                self.n_events += 1
                yield Event(eventnum, timestamp, channel, data)
        except OSError as e:
            raise LogError("%s: %s" % (self.name, e.strerror or e)) from e


def read_events(path, channels=None, **kw):
    """The events of the log at path as a list; channels: None (all) or a
    collection of channel names to keep."""
    with LogReader(path, **kw) as r:
        return [ev for ev in r if channels is None or ev.channel in channels]


class LogWriter:
    """Write an LCM log file that lcm-logplayer, lcm-spy, trk-lcm-bridge
    --replay/--summarize and LogReader read. write() numbers events from 0
    (as lcm-logger does); write_event() keeps an event's own number, so
    reading a log and writing its events gives the same bytes."""

    def __init__(self, path):
        self._f = open(path, "wb")
        self.eventnum = 0

    def write(self, channel, data, timestamp):
        self.write_event(Event(self.eventnum, timestamp, channel, data))

    def write_event(self, ev):
        ch = ev.channel.encode("utf-8", "surrogateescape") if isinstance(ev.channel, str) else bytes(ev.channel)
        if not 0 < len(ch) <= MAX_CHANNEL:
            raise ValueError("channel name of %d bytes (1..%d)" % (len(ch), MAX_CHANNEL))
        data = bytes(ev.data)
        self._f.write(_HEADER.pack(SYNC, ev.eventnum, ev.timestamp, len(ch), len(data)))
        self._f.write(ch)
        self._f.write(data)
        self.eventnum = ev.eventnum + 1

    def close(self):
        self._f.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
