"""trkcsv - read the CSV files of trk-sim (and trk-tablegen, trk-bench) into
numpy arrays.

trk-sim's CSV files are: optional comment lines starting with '#' (what the
experiment is and the settings and assumptions it ran with), one header line
of column names, then one row per line, comma-separated, with empty fields
where a value does not apply (e.g. blanding-add-arl's k, n for Page rows).

    import trkcsv
    t = trkcsv.read("build/demo-amplitude/tracks.csv")
    t.columns            # ['scan', 'time_s', 'id', ...]
    t["x_m"]             # numpy float64 array; an empty field is NaN
    t.comments           # the '#' lines, without the '#'
    t.params             # {'runs': 300, 'alpha': 0.01, ...} from "key value" pairs in them
    len(t)               # rows
    t.to_pandas()        # a pandas DataFrame (pandas optional)
    trkcsv.key_value("build/demo-amplitude/summary.csv")   # a key,value file as a dict

A column whose non-empty fields all parse as numbers is float64 (int64 when
they are all integers and none is empty); any other column is str.
Standard library and numpy.
"""

import csv
import re

import numpy as np

__all__ = ["Table", "read", "key_value", "parse_params"]

_INT = re.compile(r"^[+-]?\d+$")


def _number(s):
    try:
        return float(s)
    except ValueError:
        return None


def parse_params(comments):
    """Settings named in comment lines as "name value" pairs (a value that
    parses as a number; "name=value" too) before the line's first ';', e.g.
    "runs 300 alpha 0.01 seed 5; 99% interval" -> {'runs': 300, 'alpha':
    0.01, 'seed': 5}. A title line ("experiment: what it is") is skipped; the
    first occurrence of a name wins."""
    name = re.compile(r"^[A-Za-z_][\w.]*$")
    params = {}
    for line in comments:
        if re.match(r"^[\w-]+: ", line):
            continue
        toks = line.split(";", 1)[0].split()
        i = 0
        while i < len(toks):
            k, eq, v = toks[i].partition("=")
            if eq and name.match(k) and _number(v) is not None:
                params.setdefault(k, int(v) if _INT.match(v) else float(v))
                i += 1
            elif i + 1 < len(toks) and name.match(k) and _number(toks[i + 1]) is not None:
                v = toks[i + 1]
                params.setdefault(k, int(v) if _INT.match(v) else float(v))
                i += 2
            else:
                i += 1
    return params


class Table:
    """A CSV file's columns (numpy arrays, by name, in file order), its
    comment lines and the settings parsed from them."""

    def __init__(self, columns, data, comments, path=None):
        self.columns = list(columns)
        self.data = dict(zip(self.columns, data))
        self.comments = comments
        self.params = parse_params(comments)
        self.path = path

    def __getitem__(self, name):
        try:
            return self.data[name]
        except KeyError:
            raise KeyError("%s has no column %r (columns: %s)" % (self.path, name, ", ".join(self.columns))) from None

    def __contains__(self, name):
        return name in self.data

    def __len__(self):
        return len(self.data[self.columns[0]]) if self.columns else 0

    def rows(self, **where):
        """A Table of the rows whose columns equal the given values, e.g.
        t.rows(status=2, target=0)."""
        mask = np.ones(len(self), dtype=bool)
        for k, v in where.items():
            mask &= self[k] == v
        return Table(self.columns, [self.data[c][mask] for c in self.columns], self.comments, self.path)

    def to_pandas(self):
        import pandas as pd  # optional
        return pd.DataFrame({c: self.data[c] for c in self.columns})

    def __repr__(self):
        return "<trkcsv.Table %s: %d rows, columns %s>" % (self.path, len(self), ", ".join(self.columns))


def _column(values):
    if values and all(v != "" and _INT.match(v) for v in values):
        return np.array([int(v) for v in values], dtype=np.int64)
    nums = [float("nan") if v == "" else _number(v) for v in values]
    if all(n is not None for n in nums):
        return np.array(nums, dtype=np.float64)
    return np.array(values, dtype=str)


def read(path, typed=True):
    """The Table of a CSV file (ValueError naming the line when a row has
    another number of fields than the header); typed=False: every column
    str, as written."""
    comments, header, rows = [], None, []
    with open(path, newline="", encoding="utf-8") as f:
        for lineno, rec in enumerate(csv.reader(f), 1):
            if header is None:
                if not rec or (rec[0].startswith("#")):
                    if rec:
                        comments.append(",".join(rec)[1:].strip())
                    continue
                header = [h.strip() for h in rec]
                continue
            if not rec:
                continue
            if len(rec) != len(header):
                raise ValueError("%s:%d: %d fields, the header has %d" % (path, lineno, len(rec), len(header)))
            rows.append(rec)
    if header is None:
        raise ValueError("%s: no header line" % path)
    cols = [_column([r[i] for r in rows]) if typed else np.array([r[i] for r in rows], dtype=str)
            for i in range(len(header))]
    return Table(header, cols, comments, path)


def key_value(path):
    """A two-column key,value CSV (e.g. trk-sim demo-amplitude's summary.csv) as a
    dict; numbers become int or float."""
    t = read(path, typed=False)
    out = {}
    for k, v in zip(t[t.columns[0]], t[t.columns[1]]):
        k, v = str(k), str(v)
        n = _number(v)
        out[k] = v if n is None else (int(v) if _INT.match(v) else n)
    return out
