"""The tracker from Python: parameters, amplitude tables, the track table
(libtrk.so through ctypes; the layouts from the library, trk/_lib.py).

    import trk
    p = trk.default_params()            # trk_tracker_default_params
    p.sensor[0].meas_cov_m2 = [25, 0, 25]
    p.set_amplitude(0, trk.AmplitudeTable("amp_k1_snr15_pfa1e-2.tbl"))
    tk = trk.Tracker(p)                 # trk_tracker_init
    report, tracks = tk.process_scan(2.0, xy)   # xy: n x 2 (m)
"""
import ctypes
import math

import numpy as np

from . import _lib

_path, _c, version, _structs, _consts, _status_names = _lib.load()
library_path = _path
ST = _structs
REAL = np.dtype("f%d" % ST["detection"].fields["x_m"].size)
MAX_TRACKS = _consts["TRK_MAX_TRACKS"]
MAX_DETECTIONS = _consts["TRK_MAX_DETECTIONS"]
# a scan may hold this many; beyond MAX_DETECTIONS the library thins it (trk/tracker.h)
MAX_SCAN_DETECTIONS = _consts["TRK_MAX_SCAN_DETECTIONS"]
MAX_SENSORS = _consts["TRK_MAX_SENSORS"]
WITH_IMM = bool(_consts["TRK_WITH_IMM"])
WITH_JOINT = bool(_consts["TRK_WITH_JOINT"])
_c_real = ctypes.c_double if REAL.itemsize == 8 else ctypes.c_float
_c.trk_tracker_clutter_at.restype = ctypes.c_int
_c.trk_tracker_clutter_at.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_void_p, _c_real, _c_real,
                                      ctypes.POINTER(_c_real)]
if WITH_IMM:
    _c.trk_tracker_imm_params.restype = ctypes.c_int
    _c.trk_tracker_imm_params.argtypes = [ctypes.c_void_p, ctypes.c_double if REAL.itemsize == 8 else ctypes.c_float,
                                          ctypes.c_double if REAL.itemsize == 8 else ctypes.c_float]

# the build's constants without their TRK_ prefix (MAX_TRACKS, CONFIRM_MN, TRACK_CONFIRMED, ...)
constants = {k[4:]: v for k, v in _consts.items()}
# trk_status values by name ("TRK_E_RANGE": 3)
STATUS = {n: i for i, n in enumerate(_status_names)}


def status_name(st):
    """The C name of a trk_status ("TRK_E_RANGE")."""
    return _status_names[st] if 0 <= st < len(_status_names) else "status %d" % st


class TrkError(Exception):
    """A call refused by the library: .status (int) and .status_name."""

    def __init__(self, what, status):
        self.status = status
        self.status_name = status_name(status)
        Exception.__init__(self, "%s: %s" % (what, self.status_name))


class ParamError(TrkError, ValueError):
    """Parameters refused by trk_tracker_check_params: .field names the member
    (as the C side names it: "gate_prob", "sensor[0].pd", "confirm.u.mn")."""

    def __init__(self, field, status, accepted=""):
        self.field = field
        TrkError.__init__(self, field, status)
        if accepted:
            self.args = (self.args[0] + " (accepted: %s)" % accepted,)


def _py(v):
    if isinstance(v, np.floating):
        return float(v)
    if isinstance(v, np.integer):
        return int(v)
    return v


class View(object):
    """Members of a C struct by attribute: p.gate_prob, p.sensor[0].pd,
    p.confirm.u.mn.m. Arrays come back as numpy views (writes go to the
    struct); a struct array as a list of views."""

    def __init__(self, rec, st, prefix=""):
        object.__setattr__(self, "_rec", rec)
        object.__setattr__(self, "_st", st)
        object.__setattr__(self, "_prefix", prefix)

    def _names(self):
        n = len(self._prefix)
        return sorted({k[n:].split(".")[0] for k in self._st.fields if k.startswith(self._prefix)})

    def __dir__(self):
        return self._names()

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        full = self._prefix + name
        f = self._st.fields.get(full)
        if f is None:
            if any(k.startswith(full + ".") for k in self._st.fields):
                return View(self._rec, self._st, full + ".")
            raise AttributeError("struct %s has no member %s" % (self._st.name, full))
        v = self._rec[full]
        if f.kind == "s":
            sub = ST[f.sub]
            return View(v, sub) if f.count == 1 else [View(v[i], sub) for i in range(f.count)]
        return v if f.count > 1 else _py(v)

    def __setattr__(self, name, value):
        full = self._prefix + name
        f = self._st.fields.get(full)
        if f is None:
            raise AttributeError("struct %s has no member %s" % (self._st.name, full))
        if f.kind == "s":
            raise AttributeError("%s is a struct: set its members" % full)
        v = np.asarray(value)
        if f.kind in "iu":
            if v.dtype.kind not in "iub":
                if not np.all(np.isfinite(v.astype(float))) or np.any(v != np.round(v)):
                    raise ValueError("%s: %r is not an integer" % (full, value))
            info = np.iinfo(np.dtype("%s%d" % (f.kind, f.size)))
            if np.any(v < info.min) or np.any(v > info.max):
                raise ValueError("%s: %r outside %d .. %d" % (full, value, info.min, info.max))
        elif f.kind == "f" and v.dtype.kind not in "fiub":
            raise ValueError("%s: %r is not a number" % (full, value))
        if f.count > 1 and v.shape != (f.count,):
            raise ValueError("%s: %d values expected, got shape %s" % (full, f.count, v.shape))
        self._rec[full] = v

    def fields(self):
        """(name, value, unit, range) of every member, nested ones flattened
        ("sensor[0].pd")."""
        out = []
        for k, f in self._st.fields.items():
            if not k.startswith(self._prefix):
                continue
            if f.kind == "s":
                subs = [getattr(self, k[len(self._prefix):])] if f.count == 1 else getattr(self, k[len(self._prefix):])
                for i, s in enumerate(subs):
                    label = k if f.count == 1 else "%s[%d]" % (k, i)
                    out += [("%s.%s" % (label, n), v, u, r) for n, v, u, r in s.fields()]
            else:
                v = self._rec[k]
                out.append((k, v.tolist() if f.count > 1 else _py(v), f.unit, f.range))
        return out

    def __repr__(self):
        lines = []
        for n, v, u, r in self.fields():
            lines.append("%s = %r%s%s" % (n, v, " [%s]" % u if u else "", "  (%s)" % r if r else ""))
        return "\n".join(lines)


def _field_range(field):
    """The accepted values of a member named as trk_tracker_check_params names it."""
    name = field
    st = ST["tracker_params"]
    if name.startswith("sensor["):
        name = name.split("].", 1)[1] if "]." in name else ""
        st = ST["sensor_params"]
    f = st.fields.get(name)
    return f.range if f is not None else ""


class Params(View):
    """struct trk_tracker_params (trk/tracker.h), member by member; units and
    ranges: .fields() or repr. Amplitude models: set_amplitude*."""

    def __init__(self, fill=None):
        arr = np.zeros(1, ST["tracker_params"].dtype)
        View.__init__(self, arr[0], ST["tracker_params"])
        object.__setattr__(self, "_arr", arr)
        object.__setattr__(self, "_keep", {})  # amplitude tables the models point into, by sensor
        if fill is not None:
            fill(self._ptr())

    def _ptr(self, offset=0):
        return ctypes.c_void_p(self._arr.ctypes.data + offset)

    def copy(self):
        q = Params()
        # byte for byte: the dtype names the public members only (an
        # amplitude model's private ones would be lost field by field)
        ctypes.memmove(q._arr.ctypes.data, self._arr.ctypes.data, self._arr.nbytes)
        q._keep.update(self._keep)
        return q

    def check(self):
        """trk_tracker_check_params: ParamError naming the field and the status."""
        field = ctypes.c_char_p()
        st = _c.trk_tracker_check_params(self._ptr(), ctypes.byref(field))
        if st != 0:
            name = field.value.decode() if field.value else "params"
            raise ParamError(name, st, _field_range(name))
        return self

    def _amp_ptr(self, sensor):
        if not 0 <= sensor < MAX_SENSORS:
            raise ParamError("sensor[%d].amplitude" % sensor, STATUS["TRK_E_SENSOR"])
        off = (ST["tracker_params"].fields["sensor"].offset + sensor * ST["sensor_params"].size +
               ST["sensor_params"].fields["amplitude"].offset)
        return self._ptr(off)

    def set_amplitude(self, sensor, table):
        """Sensor's amplitude model from an AmplitudeTable (trk_amplitude_init_table;
        PDAFAI: use_amplitude = 1); None: positions only (use_amplitude = 0)."""
        if table is None:
            self.sensor[sensor].use_amplitude = 0
            self._keep.pop(sensor, None)
            return
        st = _c.trk_amplitude_init_table(self._amp_ptr(sensor), table._ptr())
        if st != 0:
            raise ParamError("sensor[%d].amplitude" % sensor, st)
        self._keep[sensor] = table
        self.sensor[sensor].use_amplitude = 1

    def set_imm(self, omega_rad_s, p_stay):
        """IMM tracks on CV and turns at +-omega_rad_s (trk_tracker_imm_params;
        builds with TRK_WITH_IMM only)."""
        if not WITH_IMM:
            raise TrkError("set_imm: this libtrk is built without TRK_WITH_IMM", STATUS["TRK_E_UNSUPPORTED"])
        st = _c.trk_tracker_imm_params(self._ptr(), omega_rad_s, p_stay)
        if st != 0:
            raise ParamError("imm", st)


def default_params():
    """trk_tracker_default_params."""
    return Params(_c.trk_tracker_default_params)


def mn_kn_params():
    """trk_tracker_mn_kn_params: M/N confirmation, K/N termination."""
    return Params(_c.trk_tracker_mn_kn_params)


class AmplitudeTable(object):
    """An amplitude table file (trk-tablegen amp) read and checked by
    trk_table_load_file; give it to Params.set_amplitude."""

    def __init__(self, path):
        self.path = path
        n = ctypes.c_size_t()
        st = _c.trk_table_file_size(path.encode(), ctypes.byref(n))
        if st != 0:
            raise TrkError(path, st)
        self._buf = np.zeros(n.value // 8 + 1, np.uint64)  # 8-byte aligned (TRK_TABLE_ALIGN)
        self._table = np.zeros(1, ST["table"].dtype)
        st = _c.trk_table_load_file(path.encode(), ctypes.c_void_p(self._buf.ctypes.data), self._buf.nbytes,
                                    self._ptr(), None)
        if st != 0:
            raise TrkError(path, st)

    def _ptr(self):
        return ctypes.c_void_p(self._table.ctypes.data)


def _track_dtype():
    """The tracks' view of struct trk_track: its members under the binding's
    names, at the library's offsets (the struct's size: a slot array viewed
    with it needs no copy)."""
    f = ST["track"].fields
    nx = constants["CV2_NX"]
    names = [("id", "id", None), ("status", "status", None), ("end_reason", "end_reason", None),
             ("stationary", "stationary", None), ("time_us", "time_us", None), ("state", "x", (nx,)), ("covariance", "p", (nx, nx)),
             ("existence", "vis.pv", None), ("confidence", "vis.pcv", None), ("n_scans", "n_scans", None),
             ("n_hits", "n_hits", None)]
    base = ST["track"].dtype
    return np.dtype({"names": [n for n, _, _ in names],
                     "formats": [(base.fields[c][0].base, shape) if shape else base.fields[c][0]
                                 for _, c, shape in names],
                     "offsets": [f[c].offset for _, c, _ in names], "itemsize": ST["track"].size})


TRACK_DTYPE = _track_dtype()


def time_us(time_s):
    """Seconds to the scan's integer microseconds, rounded half away from
    zero (C's llround)."""
    v = float(time_s) * 1e6
    r = math.floor(abs(v))
    if abs(v) - r >= 0.5:
        r += 1
    return int(math.copysign(r, v))


class Tracker(object):
    """struct trk_tracker: one call per scan. process_scan returns
    (report, tracks): the scan report (dict of its counts) and the live
    tracks in slot order as a numpy structured array (TRACK_DTYPE: id,
    status, end_reason, stationary (1: held tentative: standing still, or
    waiting with a scatterer's echoes), time_us, state [x, vx, y, vy] (m, m/s), covariance
    4 x 4, existence vis.pv, confidence vis.pcv, n_scans, n_hits; a copy of
    the track slots, laid out as struct trk_track:
    numpy.lib.recfunctions.repack_fields packs it). process_polar_scan takes
    a polar sensor's ranges and bearings; clutter_at reads the density the
    tracker uses (its clutter map)."""

    def __init__(self, params=None):
        self.params = (params if params is not None else default_params()).copy().check()
        size = ST["tracker"].size
        self._buf = np.zeros(size // 8 + 1, np.uint64)
        self._tk = ctypes.c_void_p(self._buf.ctypes.data)
        st = _c.trk_tracker_init(self._tk, self.params._ptr())
        if st != 0:
            raise TrkError("trk_tracker_init", st)
        tf = ST["tracker"].fields["track"]
        self._slots = np.ndarray((tf.count,), TRACK_DTYPE, self._buf, tf.offset)
        self._det = np.zeros(MAX_DETECTIONS, ST["detection"].dtype)
        self._polar = np.zeros(0, ST["polar_detection"].dtype)
        self._lambda = np.zeros(MAX_DETECTIONS, REAL)
        self._scan = np.zeros(1, ST["scan"].dtype)
        self._scan_p = ctypes.c_void_p(self._scan.ctypes.data)
        self._pose = np.zeros(1, ST["pose"].dtype)
        self._report = np.zeros(1, ST["scan_report"].dtype)
        self._report_p = ctypes.c_void_p(self._report.ctypes.data)
        self._process = _c.trk_tracker_process_scan

    @staticmethod
    def _room(buf, n):
        """buf, or a larger zeroed one of the same dtype when it holds fewer than n."""
        if n > MAX_SCAN_DETECTIONS:
            raise TrkError("a scan of %d detections: this build takes at most %d" % (n, MAX_SCAN_DETECTIONS),
                           STATUS["TRK_E_CAPACITY"])
        return buf if buf.shape[0] >= n else np.zeros(max(n, MAX_DETECTIONS), buf.dtype)

    def _densities(self, n, clutter_density):
        """The scan's clutter densities: None, or n values (1/m^2; one
        broadcast) copied into the scan's own array."""
        if clutter_density is None:
            self._scan["clutter_density_per_m2"] = 0
            return
        self._lambda = self._room(self._lambda, n)
        self._lambda[:n] = np.broadcast_to(np.asarray(clutter_density, dtype=float), (n,))
        self._scan["clutter_density_per_m2"] = self._lambda.ctypes.data

    def _run(self, time_s, sensor, n, pose):
        s = self._scan
        s["time_us"] = time_us(time_s)
        s["sensor_id"] = sensor
        s["n_detections"] = n
        s["has_pose"] = 0 if pose is None else 1
        if pose is not None:
            self._pose["x_m"], self._pose["y_m"], self._pose["heading_rad"] = pose
            s["pose"] = self._pose[0]
        st = self._process(self._tk, self._scan_p, self._report_p)
        if st != 0:
            raise TrkError("process_scan", st)
        return self.report(), self.tracks()

    def process_scan(self, time_s, xy, cov=None, amplitude=None, sensor=0, pose=None, clutter_density=None):
        """One scan at time_s (s; rounded to the microsecond) of sensor:
        xy (n x 2, m), cov (None: the sensor's; n x 3 [xx, xy, yy] or
        n x 2 x 2, m^2), amplitude (None, or n linear amplitudes); pose
        (x_m, y_m, heading_rad) this scan's, None: the sensor's own;
        clutter_density (None: the tracker's own, or n values per m^2,
        e.g. a CFAR's local estimates: trk_scan.clutter_density_per_m2). More
        than MAX_DETECTIONS detections are thinned by the library (the
        report counts them). A refused scan raises TrkError (the table
        untouched)."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        n = xy.shape[0]
        self._det = self._room(self._det, n)
        d = self._det[:n]
        d["x_m"] = xy[:, 0]
        d["y_m"] = xy[:, 1]
        if cov is None:
            d["has_cov"] = 0
        else:
            c = np.asarray(cov, dtype=float)
            if c.shape == (n, 2, 2):
                c = np.stack([c[:, 0, 0], c[:, 0, 1], c[:, 1, 1]], axis=1)
            d["cov_m2"] = np.broadcast_to(c, (n, 3))
            d["has_cov"] = 1
        if amplitude is None:
            d["has_amplitude"] = 0
        else:
            d["amplitude"] = np.broadcast_to(np.asarray(amplitude, dtype=float), (n,))
            d["has_amplitude"] = 1
        self._scan["detections"] = self._det.ctypes.data
        self._scan["polar"] = 0
        self._densities(n, clutter_density)
        return self._run(time_s, sensor, n, pose)

    def process_polar_scan(self, time_s, range_m, bearing_rad, amplitude=None, sensor=0, pose=None,
                           clutter_density=None):
        """One scan of a polar sensor (kind SENSOR_POLAR) at time_s: n ranges
        (m) and bearings (rad, clockwise from the pose's heading), amplitude
        and clutter_density as process_scan; pose (x_m, y_m, heading_rad) this scan's (a moving
        platform), None: the sensor's own. The library converts each
        detection and gives it its own covariance (trk_polar_to_cartesian)."""
        r = np.asarray(range_m, dtype=float).ravel()
        b = np.asarray(bearing_rad, dtype=float).ravel()
        if r.shape != b.shape:
            raise TrkError("process_polar_scan: %d ranges, %d bearings" % (r.shape[0], b.shape[0]),
                           STATUS["TRK_E_ARG"])
        n = r.shape[0]
        self._polar = self._room(self._polar, n)
        d = self._polar[:n]
        d["range_m"] = r
        d["bearing_rad"] = b
        if amplitude is None:
            d["has_amplitude"] = 0
        else:
            d["amplitude"] = np.broadcast_to(np.asarray(amplitude, dtype=float), (n,))
            d["has_amplitude"] = 1
        self._scan["detections"] = 0
        self._scan["polar"] = self._polar.ctypes.data
        self._densities(n, clutter_density)
        return self._run(time_s, sensor, n, pose)

    def clutter_at(self, x_m, y_m, sensor=0, pose=None):
        """The clutter density (1/m^2) the tracker uses at (x_m, y_m) in a scan
        of sensor from pose (None: the sensor's own): the configured one
        times its clutter map's ratio there, pooled over the window of cells
        about it, or over a quadrant of it by the edge rule
        (trk_tracker_clutter_at)."""
        pp = None
        if pose is not None:
            self._pose["x_m"], self._pose["y_m"], self._pose["heading_rad"] = pose
            pp = ctypes.c_void_p(self._pose.ctypes.data)
        out = _c_real()
        st = _c.trk_tracker_clutter_at(self._tk, sensor, pp, x_m, y_m, ctypes.byref(out))
        if st != 0:
            raise TrkError("clutter_at", st)
        return out.value

    def report(self):
        """The last scan's report (dict of struct trk_scan_report)."""
        return dict(zip(self._report.dtype.names, self._report[0].item()))

    def tracks(self):
        """The live tracks (TRACK_DTYPE), slot order."""
        return self._slots[self._slots["status"] != 0]
