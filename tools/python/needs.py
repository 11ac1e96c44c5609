"""needs.py - what a tool needs, said in plain words when it is missing
(instead of a traceback): its third-party Python packages, and its files.

    from needs import need, run_main
    need("plot_track_log.py", "numpy")        # before the imports that use it
    plt = need("gospa_grid.py", "matplotlib.pyplot")
    ...
    run_main("plot_track_log.py", main, (lcmlog.LogError,))

need() imports and returns the module; when it (or its package) is not
installed it prints, on stderr,

    plot_track_log.py: needs the Python package numpy (Debian: apt-get install
    python3-numpy; pip: pip install numpy)

(one line) and exits with status 1, a failure while running (docs/statuses.md,
"Exit codes"). run_main(prog, main, errors) runs main() and exits with its
value; a file that cannot be read or written (OSError) or one of `errors`
(e.g. lcmlog.LogError, a log that is no LCM log) is said as "prog: what" and
exits 1. Only the standard library here: it must work where nothing else is
installed.
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


def run_main(prog, main, errors=()):
    """sys.exit(main()); OSError and `errors` said in one line, exit 1."""
    try:
        rc = main()
    except OSError as e:
        what = "%s: %s" % (e.filename, e.strerror) if e.filename and e.strerror else str(e)
        print("%s: %s" % (prog, what), file=sys.stderr)
        sys.exit(1)
    except tuple(errors) as e:
        print("%s: %s" % (prog, e), file=sys.stderr)
        sys.exit(1)
    sys.exit(rc)
