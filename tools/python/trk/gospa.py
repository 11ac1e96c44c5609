"""GOSPA (generalised optimal sub-pattern assignment; Rahmathullah,
Garcia-Fernandez & Svensson, FUSION 2017) with alpha = 2, the metric of
trk-sim (tools/sim/gospa.c; tests/python_binding.sh checks that both agree).

For targets X (n) and estimates Y (m), base distance d, cut-off c > 0 and
order p >= 1:
  GOSPA^p = min over assignments g of sum_{(i,j) in g} d(x_i, y_j)^p
                                      + c^p / 2 (n + m - 2 |g|)
where only pairs with d < c are assigned. The parts: localisation (sum of
d^p over the assigned pairs), missed (c^p / 2 per target left alone), false
(c^p / 2 per estimate left alone). The assignment: a rectangular linear
assignment on min(d, c)^p, solved exactly by the Hungarian method with
potentials.
"""
from collections import namedtuple

import numpy as np

Result = namedtuple("Result", "gospa loc missed false n_assigned n_missed n_false assign")


def hungarian(cost):
    """Minimum-cost assignment of a rows x cols cost matrix, rows <= cols:
    (total cost, the column of each row)."""
    cost = np.asarray(cost, dtype=float)
    n, m = cost.shape
    if n > m:
        raise ValueError("hungarian: more rows than columns")
    INF = np.inf
    u = np.zeros(n + 1)
    v = np.zeros(m + 1)
    row_of = np.zeros(m + 1, dtype=int)  # column j (1-based) -> row (1-based), 0 free
    way = np.zeros(m + 1, dtype=int)
    for i in range(1, n + 1):
        row_of[0] = i
        j0 = 0
        minv = np.full(m + 1, INF)
        used = np.zeros(m + 1, dtype=bool)
        while True:
            used[j0] = True
            i0 = row_of[j0]
            # reduced costs of row i0 against the columns not yet in the tree
            free = ~used[1:]
            red = cost[i0 - 1] - u[i0] - v[1:]
            upd = free & (red < minv[1:])
            minv[1:][upd] = red[upd]
            way[1:][upd] = j0
            cand = np.where(free, minv[1:], INF)
            j1 = int(np.argmin(cand)) + 1
            delta = cand[j1 - 1]
            tree = np.nonzero(used)[0]
            u[row_of[tree]] += delta
            v[tree] -= delta
            minv[1:][free] -= delta
            j0 = j1
            if row_of[j0] == 0:
                break
        while j0:
            j1 = way[j0]
            row_of[j0] = row_of[j1]
            j0 = j1
    col_of = np.full(n, -1, dtype=int)
    for j in range(1, m + 1):
        if row_of[j]:
            col_of[row_of[j] - 1] = j - 1
    return float(cost[np.arange(n), col_of].sum()) if n else 0.0, col_of


def gospa_dist(dist, c, p=2.0):
    """GOSPA of an n x m distance matrix (targets x estimates)."""
    if not c > 0 or not p >= 1:
        raise ValueError("gospa: need c > 0 and p >= 1")
    d = np.asarray(dist, dtype=float)
    n, m = d.shape
    if np.any(np.isnan(d)) or np.any(d < 0):
        raise ValueError("gospa: NaN or negative distance")
    cp = c ** p
    assign = np.full(n, -1, dtype=int)
    if n and m:
        cost = np.minimum(d, c) ** p
        if n <= m:
            _, col = hungarian(cost)
            assign[:] = col
        else:
            _, col = hungarian(cost.T)
            for j, i in enumerate(col):
                assign[i] = j
        for i in range(n):
            if assign[i] >= 0 and not d[i, assign[i]] < c:
                assign[i] = -1
    pairs = assign >= 0
    loc = float(np.sum(d[np.nonzero(pairs)[0], assign[pairs]] ** p)) if pairs.any() else 0.0
    k = int(pairs.sum())
    missed = cp / 2 * (n - k)
    false = cp / 2 * (m - k)
    return Result((loc + missed + false) ** (1.0 / p), loc, missed, false, k, n - k, m - k, assign)


def gospa(targets, estimates, c, p=2.0):
    """GOSPA of target and estimate positions (n x 2 and m x 2, m), the
    base distance Euclidean."""
    x = np.asarray(targets, dtype=float).reshape(-1, 2)
    y = np.asarray(estimates, dtype=float).reshape(-1, 2)
    d = np.hypot(x[:, None, 0] - y[None, :, 0], x[:, None, 1] - y[None, :, 1])
    return gospa_dist(d.reshape(len(x), len(y)), c, p)
