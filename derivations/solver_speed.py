"""Run time of the high-accuracy solver (issue 3's speed targets), written to solver_speed.md.

Measures, after a warm-up that fills the discretisation caches: the median time of
``friction_coefficient`` (mu for given c) and ``stick_radius`` (c for given mu) at each
resolution level, and a sweep of (mu, nu) pairs. Run time: about 2 minutes.

    python derivations/solver_speed.py

Timings depend on the machine and its load; the file records the machine's core count.
It is not compared by the tests (timings are not reproducible), only run by hand.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

from numeric import flat_punch, friction_coefficient, stick_radius

HERE = Path(__file__).resolve().parent


def _median_ms(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return 1e3 * float(np.median(times))


def main() -> None:
    lines = ["# Solver run time", "", f"Machine: {os.cpu_count()} cores. Medians after warm-up.", "",
             "| level | unknowns | mu for given c (ms) | c for given mu (ms) | error estimate (c = 0.5, nu = 0.25) |",
             "|---|---|---|---|---|"]
    for level in (1, 2, 3):
        flat_punch(nu=0.25, c=0.5, level=level)  # warm-up: caches of this level and the one below
        s = flat_punch(nu=0.25, c=0.5, level=level)
        forward = _median_ms(lambda: flat_punch(nu=0.25, c=0.37, level=level), 7)
        inverse = _median_ms(lambda: flat_punch(nu=0.25, mu=0.17, level=level), 5)
        lines.append(f"| {level} | {s.route.split(', ')[1]} | {forward:.1f} | {inverse:.1f} | {s.error:.1e} |")
    rng = np.random.default_rng(0)
    pairs = list(zip(rng.uniform(0.15, 1.0, 20), rng.uniform(-0.5, 0.49, 20)))  # c >~ 5e-3: see README
    t0 = time.perf_counter()
    for mu, nu in pairs:
        flat_punch(nu=nu, mu=mu)
    per_pair = (time.perf_counter() - t0) / len(pairs)
    lines += ["", f"Sweep of {len(pairs)} random (mu, nu) pairs, mu in [0.15, 1], nu in [-0.5, 0.49], level 2: "
              f"{1e3 * per_pair:.0f} ms per pair ({1000 * per_pair:.0f} s per 1000 pairs).", ""]
    stick_radius(0.2, 0.25)  # warm-up: loads the table
    one = _median_ms(lambda: stick_radius(0.2, 0.25), 21)
    # 1000 pairs inside the table's domain: random (c, nu), mu from the table itself
    c_in = 1.0 / (1.0 + np.exp(-rng.uniform(np.log(1e-3 / (1 - 1e-3)), np.log(0.95 / 0.05), 1000)))
    nu_in = rng.uniform(-0.5, 0.49, 1000)
    mu_in = friction_coefficient(c_in, nu_in)
    t0 = time.perf_counter()
    stick_radius(mu_in, nu_in)
    batch_in = time.perf_counter() - t0
    # 200 random (mu, nu) pairs over the range; those with c > 0.95 go to the solver
    mus, nus = rng.uniform(0.15, 1.0, 200), rng.uniform(-0.5, 0.49, 200)
    t0 = time.perf_counter()
    cs = stick_radius(mus, nus)
    batch = time.perf_counter() - t0
    outside = int(np.sum(cs > 0.95))
    lines += ["## stick_radius from the Chebyshev table (numeric.core.table)", "",
              f"- One (mu, nu) pair: {one:.2f} ms median.",
              f"- 1000 pairs inside the table's domain (1e-3 <= c <= 0.95, -0.5 <= nu <= 0.5): {1e3 * batch_in:.1f} ms.",
              f"- 200 random pairs, mu in [0.15, 1], nu in [-0.5, 0.49]: {batch:.1f} s; {outside} of them have "
              "c > 0.95, outside the table, and are solved one by one (they take almost all of the time).", ""]
    (HERE / "solver_speed.md").write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
