"""The shared library behind the binding: found, loaded, its version and ABI
checked, and the layout of its public structs read from the library itself
(trk/layout.h), as numpy dtypes. Nothing here repeats an offset or a size of
the C headers.

The library is the first of:
  $TRK_LIBRARY (a path);
  the installed one beside this package (PREFIX/lib, for a package in
  PREFIX/share/trk/python/trk);
  the source tree's build directory (build/libtrk.so, build/float/libtrk_f.so);
  the system's (ctypes.util.find_library, /usr/local/lib, /usr/lib).
TRK_REAL=float selects libtrk_f.so (the float build) instead of libtrk.so.
"""
import ctypes
import ctypes.util
import os

import numpy as np

# the layout protocol this binding reads (TRK_SHARED_ABI, trk/layout.h)
SHARED_ABI = 1


class LibraryNotFound(ImportError):
    """libtrk.so was not found: the tracker is unavailable (the LCM types,
    the live receiver and GOSPA work without it)."""


class AbiError(ImportError):
    """The library found does not match this binding."""


def _candidates():
    real = os.environ.get("TRK_REAL", "double")
    if real not in ("double", "float"):
        raise AbiError("TRK_REAL must be double or float, not %r" % real)
    name = "libtrk_f.so" if real == "float" else "libtrk.so"
    if os.environ.get("TRK_LIBRARY"):
        return [os.environ["TRK_LIBRARY"]]
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", "..", ".."))
    # installed: the soname (make install puts no development link libtrk.so,
    # so that -ltrk links the static libtrk.a)
    out = [os.path.normpath(os.path.join(here, "..", "..", "..", "..", "lib", name + ".0"))]
    out.append(os.path.join(root, "build", "float", name) if real == "float" else os.path.join(root, "build", name))
    found = ctypes.util.find_library("trk_f" if real == "float" else "trk")
    if found:
        out.append(found)
    out += [os.path.join(d, n) for d in ("/usr/local/lib", "/usr/lib") for n in (name + ".0", name)]
    return out


def _load():
    tried = []
    for path in _candidates():
        if os.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            return path, ctypes.CDLL(path)
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
    raise LibraryNotFound("libtrk shared library not found (build it with `make shared`, install it with "
                          "`make install`, or set TRK_LIBRARY); tried: " + ", ".join(tried))


_c_size = ctypes.c_size_t
_c_str = ctypes.c_char_p
_P = ctypes.POINTER


def _declare(lib):
    sig = {
        "trk_shared_version": (_c_str, []),
        "trk_shared_abi_check": (ctypes.c_int, [ctypes.c_uint]),
        "trk_layout_n_structs": (_c_size, []),
        "trk_layout_struct": (ctypes.c_int, [_c_size, _P(_c_str), _P(_c_size), _P(_c_size)]),
        "trk_layout_field": (ctypes.c_int, [_c_size, _c_size, _P(_c_str), _P(ctypes.c_char), _P(_c_size),
                                            _P(_c_size), _P(_c_size), _P(_c_str), _P(_c_str), _P(_c_str)]),
        "trk_layout_n_constants": (_c_size, []),
        "trk_layout_constant": (ctypes.c_int, [_c_size, _P(_c_str), _P(ctypes.c_long)]),
        "trk_status_str": (_c_str, [ctypes.c_int]),
        "trk_tracker_default_params": (None, [ctypes.c_void_p]),
        "trk_tracker_mn_kn_params": (None, [ctypes.c_void_p]),
        "trk_tracker_check_params": (ctypes.c_int, [ctypes.c_void_p, _P(_c_str)]),
        "trk_tracker_init": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p]),
        "trk_tracker_process_scan": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]),
        "trk_tracker_sizeof": (_c_size, []),
        "trk_table_file_size": (ctypes.c_int, [_c_str, _P(_c_size)]),
        "trk_table_load_file": (ctypes.c_int, [_c_str, ctypes.c_void_p, _c_size, ctypes.c_void_p, _P(_c_size)]),
        "trk_amplitude_init_table": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p]),
    }
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args


class Field(object):
    """One member of a C struct as the library describes it."""
    __slots__ = ("name", "kind", "size", "offset", "count", "sub", "unit", "range")

    def __init__(self, **kw):
        for k, v in kw.items():
            setattr(self, k, v)


class Struct(object):
    """A C struct: name, size, its fields (by name, in order) and its numpy dtype."""

    def __init__(self, name, size, fields):
        self.name, self.size, self.fields = name, size, fields
        self.dtype = None


def _read_layout(lib):
    structs = {}
    for i in range(lib.trk_layout_n_structs()):
        name, size, nf = _c_str(), _c_size(), _c_size()
        if lib.trk_layout_struct(i, ctypes.byref(name), ctypes.byref(size), ctypes.byref(nf)) != 0:
            raise AbiError("trk_layout_struct(%d) refused" % i)
        fields = {}
        for j in range(nf.value):
            fn, kind, fs, off, cnt = _c_str(), ctypes.c_char(), _c_size(), _c_size(), _c_size()
            sub, unit, rng = _c_str(), _c_str(), _c_str()
            if lib.trk_layout_field(i, j, *[ctypes.byref(x) for x in (fn, kind, fs, off, cnt, sub, unit, rng)]) != 0:
                raise AbiError("trk_layout_field(%d, %d) refused" % (i, j))
            f = Field(name=fn.value.decode(), kind=kind.value.decode(), size=fs.value, offset=off.value,
                      count=cnt.value, sub=sub.value.decode(), unit=unit.value.decode(), range=rng.value.decode())
            fields[f.name] = f
        structs[name.value.decode()] = Struct(name.value.decode(), size.value, fields)
    for st in structs.values():
        _dtype(st, structs)
    return structs


def _dtype(st, structs):
    if st.dtype is not None:
        return st.dtype
    names, formats, offsets = [], [], []
    for f in st.fields.values():
        if f.kind == "s":
            base = _dtype(structs[f.sub], structs)
        elif f.kind == "f":
            base = np.dtype("f%d" % f.size)
        elif f.kind in "iu":
            base = np.dtype("%s%d" % (f.kind, f.size))
        elif f.kind == "p":
            base = np.dtype("u%d" % f.size)
        else:
            raise AbiError("unknown kind %r of %s.%s" % (f.kind, st.name, f.name))
        names.append(f.name)
        formats.append(base if f.count == 1 else (base, (f.count,)))
        offsets.append(f.offset)
        if f.offset + base.itemsize * f.count > st.size:
            raise AbiError("%s.%s ends beyond the struct's %d bytes" % (st.name, f.name, st.size))
    st.dtype = np.dtype({"names": names, "formats": formats, "offsets": offsets, "itemsize": st.size})
    return st.dtype


def _read_constants(lib):
    out = {}
    for i in range(lib.trk_layout_n_constants()):
        name, value = _c_str(), ctypes.c_long()
        if lib.trk_layout_constant(i, ctypes.byref(name), ctypes.byref(value)) != 0:
            raise AbiError("trk_layout_constant(%d) refused" % i)
        out[name.value.decode()] = value.value
    return out


# the members the binding reads or writes by name: a library without them is refused
_NEEDED = {
    "tracker_params": ("n_sensors", "sensor"),
    "sensor_params": ("pd", "meas_cov_m2", "clutter_density_per_m2", "use_amplitude", "amplitude"),
    "detection": ("x_m", "y_m", "cov_m2", "amplitude", "has_cov", "has_amplitude"),
    "scan": ("time_us", "sensor_id", "n_detections", "detections"),
    "track": ("id", "status", "end_reason", "time_us", "x", "p", "n_scans", "n_hits", "vis.pv", "vis.pcv"),
    "tracker": ("track",),
    "table": (),
    "scan_report": (),
}


def load():
    """(path, lib, version, structs, constants, status names): the library
    loaded and checked. Raises LibraryNotFound or AbiError."""
    path, lib = _load()
    try:
        _declare(lib)
    except AttributeError as e:
        raise AbiError("%s is no trk shared library of this binding: %s" % (path, e))
    st = lib.trk_shared_abi_check(SHARED_ABI)
    if st != 0:
        raise AbiError("%s refused the binding's ABI %d: %s" % (path, SHARED_ABI, lib.trk_status_str(st).decode()))
    structs = _read_layout(lib)
    for sname, members in _NEEDED.items():
        if sname not in structs:
            raise AbiError("%s does not describe struct %s" % (path, sname))
        missing = [m for m in members if m not in structs[sname].fields]
        if missing:
            raise AbiError("%s: struct %s lacks %s" % (path, sname, ", ".join(missing)))
    if structs["tracker"].size != lib.trk_tracker_sizeof():
        raise AbiError("%s: the layout's struct trk_tracker (%d bytes) is not trk_tracker_sizeof() (%d)" %
                       (path, structs["tracker"].size, lib.trk_tracker_sizeof()))
    consts = _read_constants(lib)
    status = [lib.trk_status_str(i).decode() for i in range(consts["TRK_STATUS_COUNT"])]
    return path, lib, lib.trk_shared_version().decode(), structs, consts, status
