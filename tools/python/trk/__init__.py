"""trk from Python (docs/python.md).

The LCM types of trk's messages (lcm-gen -p output, the modules *_t.py of
this package: trk.detection_t, trk.track_list_t, ...), a pure-Python
receiver of LCM's UDP multicast (trk.lcm_udpm, python3 -m trk.live), GOSPA
(trk.gospa), and the tracker itself through libtrk.so (trk.binding:
default_params, Tracker, AmplitudeTable), loaded and checked (version, ABI)
at import. Without the library the rest works and trk.library_error says
why the tracker is missing.
"""
from .bridge_status_t import bridge_status_t
from .detection_scan_polar_t import detection_scan_polar_t
from .detection_scan_t import detection_scan_t
from .detection_t import detection_t
from .polar_detection_t import polar_detection_t
from .track_list_t import track_list_t
from .track_t import track_t

__version__ = "0.1.0"

from ._lib import AbiError, LibraryNotFound  # noqa: E402

library_error = None
try:
    from .binding import (STATUS, TRACK_DTYPE, AmplitudeTable, ParamError, Params, Tracker,  # noqa: F401
                          TrkError, constants, default_params, library_path, mn_kn_params, status_name,
                          time_us)
    from .binding import version as library_version  # noqa: F401
    from . import binding as _binding
    if _binding.version != __version__:
        raise AbiError("%s is version %s, this binding %s" % (_binding.library_path, _binding.version, __version__))
    globals().update(_binding.constants)  # trk.MAX_TRACKS, trk.CONFIRM_MN, trk.TRACK_CONFIRMED, ...
    REAL = _binding.REAL
except LibraryNotFound as e:
    library_error = e
