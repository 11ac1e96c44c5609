"""A receiver of LCM's UDP multicast transport (udpm://) in pure Python: the
standard library's sockets, no LCM module (Debian ships none for Python).

The wire format (LCM's "UDP Multicast Protocol Description"), big-endian:
  short message, one datagram:
    uint32 magic 0x4c433032 ("LC02"), uint32 sequence number,
    the channel name (UTF-8, NUL-terminated), the payload
  fragmented message, one datagram per fragment:
    uint32 magic 0x4c433033 ("LC03"), uint32 sequence number,
    uint32 payload size, uint32 offset of this fragment in the payload,
    uint16 fragment number, uint16 fragments in the message,
    fragment 0 only: the channel name (NUL-terminated); then the fragment's
    bytes of the payload
A fragmented message is complete when every fragment arrived; a fragment of a
newer message from the same sender drops the unfinished one (counted).

    rx = Receiver("udpm://239.255.76.67:7667?ttl=0")
    for channel, payload in rx.messages(timeout_s=5):
        ...
"""
import socket
import struct
import time

MAGIC_SHORT = 0x4C433032
MAGIC_FRAG = 0x4C433033
DEFAULT_URL = "udpm://239.255.76.67:7667?ttl=0"
_SHORT = struct.Struct(">II")
_FRAG = struct.Struct(">IIIIHH")


def parse_url(url):
    """(group, port, options) of "udpm://GROUP:PORT?key=value&..."."""
    if not url.startswith("udpm://"):
        raise ValueError("not an udpm:// URL: %r" % url)
    rest = url[len("udpm://"):]
    rest, _, query = rest.partition("?")
    group, _, port = rest.partition(":")
    opts = dict(kv.partition("=")[::2] for kv in query.split("&") if kv)
    return group or "239.255.76.67", int(port or 7667), opts


class Reassembler(object):
    """Datagrams in, complete (channel, payload) messages out; per sender
    (its address) one message in assembly. Counts: short, fragmented,
    dropped (incomplete, superseded), bad (malformed datagrams)."""

    def __init__(self):
        self.partial = {}
        self.n_short = self.n_fragmented = self.n_dropped = self.n_bad = 0

    def feed(self, data, sender=None):
        """The message the datagram completes, (channel, payload), or None."""
        if len(data) < 4:
            self.n_bad += 1
            return None
        magic = struct.unpack_from(">I", data)[0]
        if magic == MAGIC_SHORT and len(data) >= _SHORT.size:
            end = data.find(b"\0", _SHORT.size)
            if end < 0:
                self.n_bad += 1
                return None
            self.n_short += 1
            return data[_SHORT.size:end].decode("utf-8", "replace"), bytes(data[end + 1:])
        if magic != MAGIC_FRAG or len(data) < _FRAG.size:
            self.n_bad += 1
            return None
        _, seq, size, offset, frag_no, n_frags = _FRAG.unpack_from(data)
        body = data[_FRAG.size:]
        if frag_no >= n_frags:
            self.n_bad += 1
            return None
        cur = self.partial.get(sender)
        if cur is not None and (cur["seq"] != seq or cur["size"] != size or cur["n"] != n_frags):
            self.n_dropped += 1
            cur = None
        if cur is None:
            cur = {"seq": seq, "size": size, "n": n_frags, "buf": bytearray(size), "got": set(), "channel": None}
            self.partial[sender] = cur
        if frag_no == 0:
            end = body.find(b"\0")
            if end < 0:
                self.n_bad += 1
                return None
            cur["channel"] = body[:end].decode("utf-8", "replace")
            body = body[end + 1:]
        if offset + len(body) > size:
            self.n_bad += 1
            return None
        cur["buf"][offset:offset + len(body)] = body
        cur["got"].add(frag_no)
        if len(cur["got"]) == n_frags and cur["channel"] is not None:
            del self.partial[sender]
            self.n_fragmented += 1
            return cur["channel"], bytes(cur["buf"])
        return None


class Receiver(object):
    """A socket joined to the URL's multicast group (SO_REUSEADDR: other LCM
    programs on the same port keep receiving)."""

    def __init__(self, url=None, bufsize=1 << 21):
        self.group, self.port, _ = parse_url(url or DEFAULT_URL)
        s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        if hasattr(socket, "SO_REUSEPORT"):
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
        try:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, bufsize)
        except OSError:
            pass
        s.bind(("", self.port))
        mreq = struct.pack("4s4s", socket.inet_aton(self.group), socket.inet_aton("0.0.0.0"))
        s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, mreq)
        self.sock = s
        self.asm = Reassembler()

    def messages(self, timeout_s=None, channels=None):
        """Complete messages (channel, payload) as they arrive, of the given
        channels (None: all); ends after timeout_s without a datagram."""
        self.sock.settimeout(timeout_s)
        while True:
            try:
                data, sender = self.sock.recvfrom(65536)
            except socket.timeout:
                return
            m = self.asm.feed(data, sender)
            if m is not None and (channels is None or m[0] in channels):
                yield m

    def close(self):
        self.sock.close()


def fragment(channel, payload, seq, max_payload=1423):
    """The datagrams LCM would send for a message (short when it fits in
    one, else fragments of at most max_payload bytes): for tests."""
    ch = channel.encode() + b"\0"
    if len(ch) + len(payload) + _SHORT.size <= max_payload + _FRAG.size:
        return [_SHORT.pack(MAGIC_SHORT, seq) + ch + payload]
    first = max(0, max_payload - len(ch))
    parts = [payload[:first]]
    off = first
    while off < len(payload):
        parts.append(payload[off:off + max_payload])
        off += max_payload
    out, off = [], 0
    for i, p in enumerate(parts):
        out.append(_FRAG.pack(MAGIC_FRAG, seq, len(payload), off, i, len(parts)) + (ch if i == 0 else b"") + p)
        off += len(p)
    return out


def now_s():
    return time.monotonic()
