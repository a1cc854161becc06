"""Integrators against the drift of a conserved quantity, over long runs of bank scenes.

Run:  python benchmarks/bench_integrators.py [--quick]
Writes docs/integrators.csv and, with matplotlib (pip install -e ".[charts]"),
docs/integrators.png and docs/integrators.svg.

For each scene (simple pendulum, double pendulum — chaotic at the energy used —, Kepler, the
rotating hoop) and each of scipy's RK45, DOP853, Radau, LSODA at rtol = atol = 1e-6, 1e-9, 1e-12,
and a symplectic Störmer–Verlet (leapfrog) where the Hamiltonian is separable (constant mass
matrix, forces from q alone: the simple pendulum), the run is timed and the drift of each
conserved quantity is measured: max |Q(t) − Q(0)| over the run, divided by the size of Q's terms
at t = 0 (Σ |term|), so that a quantity that happens to be near zero is not flattered.
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.integrate import METHOD, RTOL, integrate, parameter_values, right_hand_side  # noqa: E402
from lagrade.bank.registry import get_scene, scene_ids  # noqa: E402
from lagrade.mechanics import lagrange as mech  # noqa: E402

DOCS = ROOT / "docs"
METHODS = ("RK45", "DOP853", "Radau", "LSODA")
TOLERANCES = (1e-6, 1e-9, 1e-12)
#: Radau at 1e-12 costs 4–23 s per run even at a tenth of these lengths (measured with --quick)
#: for drifts no better than DOP853's: it is left out of the long runs to keep them bounded.
SKIP = {("Radau", 1e-12)}


@dataclass(frozen=True)
class Case:
    scene: str
    y0: tuple[float, ...]
    t_end: float
    note: str


CASES = (
    Case("simple_pendulum", (1.0, 0.0), 500.0, "released at 1 rad, ~100 periods"),
    Case("double_pendulum", (2.0, 2.5, 0.0, 0.0), 200.0, "released at (2, 2.5) rad: chaotic"),
    Case("kepler", (1.0, 0.0, 0.0, 1.2), 200.0, "eccentric bound orbit (θ̇₀ = 1.2, below circular)"),
    Case("hoop", (0.5, 0.3), 500.0, "bead on the rotating hoop; Jacobi integral h"),
)


def conserved(variant) -> dict[str, sp.Expr]:
    """The scene's conserved quantities: h (when ∂L/∂t = 0) and momenta of cyclic coordinates."""
    return dict(variant.system.conserved_quantities)


def drift(variant, expr: sp.Expr, params, ts: np.ndarray, ys: np.ndarray) -> float:
    """max |Q(t) − Q(0)| / Σ|terms of Q at t = 0|."""
    jets = variant.jets
    args = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    expr = expr.xreplace(params)
    f = sp.lambdify(args, expr, "numpy")
    values = np.asarray(f(ts, *ys), dtype=float) * np.ones_like(ts)
    terms = sp.Add.make_args(sp.expand(expr))
    scale = sum(abs(float(sp.lambdify(args, term, "numpy")(ts[0], *ys[:, 0]))) for term in terms)
    return float(np.max(np.abs(values - values[0])) / (scale or 1.0))


def verlet(variant, params_values, y0, t_end: float, h: float):
    """Störmer–Verlet (velocity form) for M q̈ = b(q) with constant M: symplectic, so the energy
    error stays bounded (∝ h²) instead of growing."""
    rhs = right_hand_side(variant, params_values)
    n = len(variant.jets)
    steps = int(round(t_end / h))
    q = np.array(y0[:n], dtype=float)
    v = np.array(y0[n:], dtype=float)
    every = max(1, steps // 2000)
    ts, ys = [0.0], [np.concatenate([q, v])]
    a = rhs(0.0, np.concatenate([q, v]))[n:]
    for k in range(1, steps + 1):
        v_half = v + 0.5 * h * a
        q = q + h * v_half
        a = rhs(k * h, np.concatenate([q, v_half]))[n:]
        v = v_half + 0.5 * h * a
        if k % every == 0:
            ts.append(k * h)
            ys.append(np.concatenate([q, v]))
    return np.array(ts), np.array(ys).T, steps


def separable(variant) -> bool:
    """Constant mass matrix and forces from q alone: H = T(p) + V(q)."""
    jets = variant.jets
    M, b = variant.system.mass_matrix, variant.system.forcing
    moving = {j.q for j in jets} | {j.dot for j in jets} | {mech.t}
    return not (M.free_symbols & moving) and not (
        b.free_symbols & ({j.dot for j in jets} | {mech.t})
    )


def run(cases, methods, tolerances) -> list[dict]:
    rows = []
    for case in cases:
        if case.scene not in scene_ids():
            print(f"(scene {case.scene} not in the bank: skipped)")
            continue
        variant = get_scene(case.scene).default
        params = parameter_values(variant)
        quantities = conserved(variant)
        t_eval = np.linspace(0.0, case.t_end, 2001)
        for method in methods:
            for tol in tolerances:
                if (method, tol) in SKIP:
                    continue
                start = time.perf_counter()
                try:
                    sol = integrate(
                        variant,
                        case.y0,
                        case.t_end,
                        method=method,
                        rtol=tol,
                        atol=tol,
                        t_eval=t_eval,
                    )
                    seconds, ok, nfev = time.perf_counter() - start, True, sol.nfev
                    drifts = {
                        k: drift(variant, q, params, sol.t, sol.y) for k, q in quantities.items()
                    }
                except Exception as error:  # noqa: BLE001 - a failed run is a result, recorded
                    seconds, ok, nfev, drifts = time.perf_counter() - start, False, 0, {}
                    print(f"  {case.scene} {method} {tol:g}: failed: {error}")
                rows.append(_row(case, method, tol, seconds, nfev, ok, drifts))
                print(
                    f"{case.scene:16} {method:7} tol {tol:7.0e}  {seconds:7.2f} s  nfev {nfev:8}  "
                    + "  ".join(f"drift {k} {v:.2e}" for k, v in drifts.items()),
                    flush=True,
                )
        if separable(variant):
            for h in (0.01, 0.001):
                start = time.perf_counter()
                ts, ys, steps = verlet(variant, None, case.y0, case.t_end, h)
                seconds = time.perf_counter() - start
                drifts = {k: drift(variant, q, params, ts, ys) for k, q in quantities.items()}
                rows.append(_row(case, "Verlet", h, seconds, steps, True, drifts, step=True))
                print(
                    f"{case.scene:16} Verlet  h {h:7.0e}  {seconds:7.2f} s  steps {steps:8}  "
                    + "  ".join(f"drift {k} {v:.2e}" for k, v in drifts.items()),
                    flush=True,
                )
    return rows


def _row(case, method, tol, seconds, nfev, ok, drifts, step=False) -> dict:
    worst = max(drifts.values()) if drifts else float("nan")
    return {
        "scene": case.scene,
        "method": method,
        "tolerance": "" if step else f"{tol:.0e}",
        "step": f"{tol:g}" if step else "",
        "t_end": case.t_end,
        "seconds": f"{seconds:.3f}",
        "evaluations": nfev,
        "success": int(ok),
        "drift": f"{worst:.3e}",
        "drifts": "; ".join(f"{k}={v:.3e}" for k, v in drifts.items()),
        "note": case.note,
    }


def choose(rows) -> dict | None:
    """The fastest (method, tolerance) whose drift stays below 1e-8 in every scene (total time)."""
    totals: dict[tuple[str, str], list] = {}
    scenes = {r["scene"] for r in rows}
    for r in rows:
        if r["tolerance"]:
            totals.setdefault((r["method"], r["tolerance"]), []).append(r)
    fit = [
        (sum(float(r["seconds"]) for r in rs), key)
        for key, rs in totals.items()
        if len(rs) == len(scenes) and all(r["success"] and float(r["drift"]) < 1e-8 for r in rs)
    ]
    if not fit:
        return None
    seconds, (method, tol) = min(fit)
    return {"method": method, "tolerance": tol, "seconds": seconds}


def write_csv(rows, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


def chart(rows, stem: Path) -> bool:
    try:
        import matplotlib  # noqa: PLC0415
    except ImportError:
        print('matplotlib is not installed: no chart drawn (pip install -e ".[charts]").')
        return False
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "lagrade-integrators"
    import matplotlib.pyplot as plt  # noqa: PLC0415
    import matplotlib.ticker  # noqa: PLC0415

    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 4.4), dpi=110, sharey=True)
    axes = np.atleast_1d(axes)
    colors = {
        "RK45": "tab:blue",
        "DOP853": "tab:green",
        "Radau": "tab:red",
        "LSODA": "tab:orange",
        "Verlet": "tab:purple",
    }
    for ax, scene in zip(axes, scenes, strict=True):
        for method in colors:
            sel = [
                r for r in rows if r["scene"] == scene and r["method"] == method and r["success"]
            ]
            if not sel:
                continue
            xs = [float(r["seconds"]) for r in sel]
            ys = [max(float(r["drift"]), 1e-17) for r in sel]
            ax.plot(xs, ys, "o-", color=colors[method], label=method, ms=4)
            for r, x, y in zip(sel, xs, ys, strict=True):
                tag = r["tolerance"] or f"h={r['step']}"
                if method == METHOD and r["tolerance"] == f"{RTOL:.0e}":
                    ax.scatter([x], [y], marker="*", s=220, color="black", zorder=4)
                ax.annotate(tag, (x, y), textcoords="offset points", xytext=(3, 3), fontsize=6)
        ax.axhline(1e-8, color="gray", ls=":", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_title(scene.replace("_", " "), fontsize=10)
        ax.set_xlabel("wall time (s, log)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("relative drift of the conserved quantity (log)")
    axes[0].legend(fontsize=7)
    fig.suptitle(
        f"Integrators: time against drift (★ default {METHOD}, rtol = atol = {RTOL:g}; "
        "dotted: 1e-8)",
        fontsize=10,
    )
    fig.tight_layout()
    fig.savefig(stem.with_suffix(".png"), metadata={"Software": None})
    fig.savefig(stem.with_suffix(".svg"), metadata={"Date": None, "Creator": None})
    plt.close(fig)
    return True


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--quick", action="store_true", help="one tenth of each run's length")
    parser.add_argument("--out", type=Path, default=DOCS / "integrators.csv")
    args = parser.parse_args()
    cases = CASES
    if args.quick:
        cases = tuple(Case(c.scene, c.y0, c.t_end / 10, c.note) for c in CASES)
    rows = run(cases, METHODS, TOLERANCES)
    write_csv(rows, args.out)
    print(f"wrote {args.out}")
    best = choose(rows)
    if best:
        print(
            f"fastest with drift < 1e-8 in every scene: {best['method']} at rtol = atol = "
            f"{best['tolerance']} ({best['seconds']:.2f} s over all scenes)"
        )
    if chart(rows, args.out.with_suffix("")):
        print(f"wrote {args.out.with_suffix('.png').name} and {args.out.with_suffix('.svg').name}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
