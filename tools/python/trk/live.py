"""python3 -m trk.live - the bridge's tracks as they arrive (LCM UDP
multicast, trk.lcm_udpm; decoded with the lcm-gen types trk.track_list_t,
trk.bridge_status_t).

    python3 -m trk.live [--url udpm://239.255.76.67:7667?ttl=0]
                        [--channel TRK_TRACKS] [--count N] [--timeout S]
                        [--plot] [--all]

Prints one line per track list (sequence, time, counts) and one per
confirmed track (--all: every track), and the bridge's status messages.
--plot draws the confirmed tracks' positions live with matplotlib when it
is installed (else says so and prints). Ends after --count track lists or
--timeout seconds without a message (default: never). The URL defaults to
$LCM_DEFAULT_URL, else LCM's default group.
"""
import argparse
import struct
import os
import sys

from . import lcm_udpm
from .bridge_status_t import bridge_status_t
from .track_list_t import track_list_t
from .track_t import track_t

STATUS = {track_t.STATUS_TENTATIVE: "tentative", track_t.STATUS_CONFIRMED: "confirmed",
          track_t.STATUS_TERMINATED: "terminated"}


def format_list(m, every):
    conf = sum(1 for t in m.tracks[:m.n_tracks] if t.status == track_t.STATUS_CONFIRMED)
    lines = ["tracks seq %d t %.3f s: %d tracks, %d confirmed, detections %d (rejected %d)" % (
        m.seq, m.utime * 1e-6, m.n_tracks, conf, m.n_detections, m.n_detections_rejected)]
    for t in m.tracks[:m.n_tracks]:
        if every or t.status == track_t.STATUS_CONFIRMED:
            lines.append("  id %d %s x %.1f y %.1f vx %.2f vy %.2f sd %.1f m" % (
                t.id, STATUS.get(t.status, "?"), t.x[0], t.x[2], t.x[1], t.x[3],
                max(t.p[0], t.p[10], 0) ** 0.5))
    return "\n".join(lines)


def _plotter():
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    plt.ion()
    fig, ax = plt.subplots()
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    trails = {}

    def draw(m):
        for t in m.tracks[:m.n_tracks]:
            if t.status == track_t.STATUS_CONFIRMED:
                trails.setdefault(t.id, []).append((t.x[0], t.x[2]))
        ax.clear()
        for tid, pts in trails.items():
            xs, ys = zip(*pts)
            ax.plot(xs, ys, "-")
            ax.annotate(str(tid), pts[-1])
        ax.set_title("trk tracks, seq %d" % m.seq)
        plt.pause(0.001)
    return draw


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m trk.live", description=__doc__.split("\n")[0])
    ap.add_argument("--url", default=os.environ.get("LCM_DEFAULT_URL") or lcm_udpm.DEFAULT_URL)
    ap.add_argument("--channel", default="TRK_TRACKS")
    ap.add_argument("--status-channel", default="TRK_BRIDGE_STATUS")
    ap.add_argument("--count", type=int, default=0, help="stop after N track lists (0: never)")
    ap.add_argument("--timeout", type=float, default=None, help="stop after S seconds without a message")
    ap.add_argument("--plot", action="store_true", help="plot with matplotlib when installed")
    ap.add_argument("--all", action="store_true", help="print every track, not only confirmed ones")
    a = ap.parse_args(argv)
    draw = _plotter() if a.plot else None
    if a.plot and draw is None:
        print("trk.live: matplotlib not installed: printing only", file=sys.stderr)
    rx = lcm_udpm.Receiver(a.url)
    n = bad = 0
    try:
        for ch, payload in rx.messages(a.timeout, {a.channel, a.status_channel}):
            try:
                if ch == a.status_channel:
                    s = bridge_status_t.decode(payload)
                    print("status: scans received %d, processed %d, rejected %d" % (
                        s.n_received, s.n_processed, s.n_rejected))
                    continue
                m = track_list_t.decode(payload)
            except (ValueError, struct.error) as e:
                bad += 1
                print("trk.live: undecodable message on %s: %s" % (ch, e), file=sys.stderr)
                continue
            print(format_list(m, a.all))
            sys.stdout.flush()
            if draw:
                draw(m)
            n += 1
            if a.count and n >= a.count:
                break
    except KeyboardInterrupt:
        pass
    finally:
        rx.close()
    asm = rx.asm
    print("trk.live: %d track lists; datagrams: %d short, %d fragmented messages, %d dropped, %d bad; "
          "%d undecodable" % (n, asm.n_short, asm.n_fragmented, asm.n_dropped, asm.n_bad, bad))
    return 0


if __name__ == "__main__":
    sys.exit(main())
