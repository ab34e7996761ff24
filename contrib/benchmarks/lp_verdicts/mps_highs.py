#!/usr/bin/python3
"""Solve a free MPS file (as masonry's `Export MPS file` writes it) with
HiGHS through scipy.optimize.linprog, independently of masonry's solvers.

    /usr/bin/python3 mps_highs.py FILE.mps [highs-ds|highs-ipm|highs] [no-presolve]

prints one JSON line: status (optimal, infeasible, unbounded, failed), the
objective of the file's minimisation, the solver's CPU seconds (reading the
file excluded) and, when optimal, the largest violation of a row or column
bound by the returned point.
"""
import json
import sys
import time

import numpy as np
import scipy.sparse as sp
from scipy.optimize import linprog

INF = 1e30


def read_free_mps(path):
    """Rows, columns, objective, bounds and matrix of a free MPS file
    (sections ROWS, COLUMNS, RHS, RANGES, BOUNDS; no integer markers)."""
    section = None
    row_type, row_index, objective_row = {}, {}, None
    col_index, cost = {}, []
    entries_r, entries_c, entries_v = [], [], []
    rhs, ranges, bounds = {}, {}, {}
    with open(path) as f:
        for line in f:
            if not line.strip() or line.startswith("*"):
                continue
            if not line[0].isspace():
                section = line.split()[0]
                continue
            t = line.split()
            if section == "ROWS":
                if t[0] == "N":
                    if objective_row is None:
                        objective_row = t[1]
                    continue
                row_index[t[1]] = len(row_index)
                row_type[t[1]] = t[0]
            elif section == "COLUMNS":
                if t[1] == "'MARKER'":
                    raise ValueError("integer markers are not supported")
                j = col_index.setdefault(t[0], len(col_index))
                if j == len(cost):
                    cost.append(0.0)
                for name, value in zip(t[1::2], t[2::2]):
                    if name == objective_row:
                        cost[j] += float(value)
                    else:
                        entries_r.append(row_index[name])
                        entries_c.append(j)
                        entries_v.append(float(value))
            elif section == "RHS":
                for name, value in zip(t[1::2], t[2::2]):
                    if name != objective_row:
                        rhs[name] = float(value)
            elif section == "RANGES":
                for name, value in zip(t[1::2], t[2::2]):
                    ranges[name] = float(value)
            elif section == "BOUNDS":
                kind, col = t[0], t[2]
                value = float(t[3]) if len(t) > 3 else 0.0
                lower, upper = bounds.get(col, (0.0, INF))
                if kind == "UP":
                    upper = value
                    if value < 0 and lower == 0.0:
                        lower = -INF
                elif kind == "LO":
                    lower = value
                elif kind == "FX":
                    lower = upper = value
                elif kind == "FR":
                    lower, upper = -INF, INF
                elif kind == "MI":
                    lower = -INF
                elif kind == "PL":
                    upper = INF
                else:
                    raise ValueError("bound type " + kind)
                bounds[col] = (lower, upper)
    m, n = len(row_index), len(col_index)
    row_lower = np.full(m, -np.inf)
    row_upper = np.full(m, np.inf)
    for name, i in row_index.items():
        b = rhs.get(name, 0.0)
        kind = row_type[name]
        if kind == "E":
            row_lower[i] = row_upper[i] = b
            if name in ranges:
                r = ranges[name]
                if r > 0:
                    row_upper[i] = b + abs(r)
                else:
                    row_lower[i] = b - abs(r)
        elif kind == "L":
            row_upper[i] = b
            if name in ranges:
                row_lower[i] = b - abs(ranges[name])
        elif kind == "G":
            row_lower[i] = b
            if name in ranges:
                row_upper[i] = b + abs(ranges[name])
    col_lower = np.zeros(n)
    col_upper = np.full(n, np.inf)
    for name, (lower, upper) in bounds.items():
        j = col_index[name]
        col_lower[j] = -np.inf if lower <= -INF else lower
        col_upper[j] = np.inf if upper >= INF else upper
    a = sp.csr_matrix((entries_v, (entries_r, entries_c)), shape=(m, n))
    return np.array(cost), a, row_lower, row_upper, col_lower, col_upper


def solve(path, method="highs-ds", presolve=True):
    c, a, rl, ru, cl, cu = read_free_mps(path)
    # linprog takes A_ub x <= b_ub and A_eq x = b_eq
    eq = rl == ru
    upper = (~eq) & np.isfinite(ru)
    lower = (~eq) & np.isfinite(rl)
    a_ub = sp.vstack([a[upper], -a[lower]]).tocsr()
    b_ub = np.concatenate([ru[upper], -rl[lower]])
    start = time.process_time()
    result = linprog(c,
                     A_ub=a_ub if a_ub.shape[0] else None,
                     b_ub=b_ub if a_ub.shape[0] else None,
                     A_eq=a[eq] if eq.any() else None,
                     b_eq=rl[eq] if eq.any() else None,
                     bounds=np.column_stack([np.where(np.isfinite(cl), cl, None),
                                             np.where(np.isfinite(cu), cu, None)]),
                     method=method, options={"presolve": presolve})
    seconds = time.process_time() - start
    status = {0: "optimal", 2: "infeasible", 3: "unbounded"}.get(result.status, "failed")
    out = {"status": status, "cpu_seconds": seconds, "message": result.message}
    if status == "optimal":
        x = result.x
        ax = a @ x
        violation = max(0.0,
                        float(np.max(np.concatenate([rl - ax, ax - ru, cl - x, x - cu]), initial=0.0)))
        out["objective"] = float(c @ x)
        out["max_violation"] = violation
    return out


if __name__ == "__main__":
    print(json.dumps(solve(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "highs-ds",
                           len(sys.argv) <= 3 or sys.argv[3] != "no-presolve")))
