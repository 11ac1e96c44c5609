"""needs.py - a tool's third-party Python packages, named in plain words when
one is missing (instead of a ModuleNotFoundError traceback):

    from needs import need
    need("plot_track_log.py", "numpy")        # before the imports that use it
    plt = need("gospa_grid.py", "matplotlib.pyplot")

need() imports and returns the module; when it (or its package) is not
installed it prints, on stderr,

    plot_track_log.py: needs the Python package numpy (Debian: apt-get install
    python3-numpy; pip: pip install numpy)

(one line) and exits with status 1, a failure while running (docs/statuses.md,
"Exit codes"). Only the standard library here: it must work where nothing else
is installed.
"""

import importlib
import sys


def missing_message(prog, package):
    """The one line need() prints for a missing package."""
    return "%s: needs the Python package %s (Debian: apt-get install %s; pip: pip install %s)" % (
        prog, package, "python3-" + package, package)


def need(prog, module):
    """Import module ("numpy", "matplotlib.pyplot") or exit 1 naming its package."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        # the package that is missing: the one the error names, else module's own
        package = (getattr(e, "name", None) or module).split(".")[0]
        print(missing_message(prog, package), file=sys.stderr)
        sys.exit(1)
