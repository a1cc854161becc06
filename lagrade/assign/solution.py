"""A scene variant's full reference solution as plain data, text or LaTeX, for `lagrade bank show`
and for anything that stores or compares solutions (expressions as strings in the students'
notation: `theta_dot`, `**`)."""

from __future__ import annotations

import json
from typing import Any

import sympy as sp

from lagrade.assign.phase_solution import phase_data, phase_lines
from lagrade.mechanics import SceneVariant
from lagrade.notation import symbol_names


def expression_text(expr: sp.Expr) -> str:
    """An expression in the project's plain notation (`theta_dot`, `**`), as sympy prints it."""
    return sp.sstr(expr)


def latex_symbol_names(variant: SceneVariant) -> dict[sp.Symbol, str]:
    """LaTeX for jet symbols: `theta_dot` → \\dot{\\theta}, `x_M_ddot` → \\ddot{x}_{M}."""
    return symbol_names(variant.coordinates)


def energy_function_name(variant: SceneVariant) -> str:
    """What to call the energy function h in this variant's text: h, unless a parameter or
    coordinate is already called h (the wedge's height), then H, then E_J."""
    taken = set(variant.parameter_symbols) | set(variant.coordinates)
    return next(n for n in ("h", "H", "E_J") if n not in taken)


def solution_data(variant: SceneVariant) -> dict[str, Any]:
    """The five-step solution as JSON-ready data (a scene given by its Lagrangian has no bodies:
    its DOF, T and V are null and it has no constraints or transformation equations)."""
    system = variant.system
    text = expression_text
    if variant.scene.given_by_lagrangian:
        bodies: dict[str, Any] = {"dof": None, "constraints": [], "transformation": {}}
        bodies |= {"T": None, "V": None}
    else:
        bodies = {
            "dof": variant.dof,
            "constraints": [
                {"kind": kind, "expression": text(f)} for kind, f in variant.constraints if f != 0
            ]
            + [{"kind": kind, "expression": ""} for kind, f in variant.constraints if f == 0],
            "transformation": {k: text(v) for k, v in variant.transformation.items()},
            "T": text(variant.kinetic_energy),
            "V": text(variant.potential_energy),
        }
    nonconservative: dict[str, Any] = {}
    if variant.scene.nonconservative:  # only then: the bank's solutions keep their shape
        nonconservative["dissipation"] = text(variant.dissipation)
        nonconservative["forces"] = {
            q: text(f)
            for q, f in zip(variant.coordinates, variant.generalized_forces, strict=True)
            if f != 0
        }
    return {
        "id": variant.scene.id,
        "title": variant.scene.title,
        "seed": variant.seed,
        "statement": variant.statement(),
        "coordinates": list(variant.coordinates),
        "parameters": {
            p.name: {
                "domain": p.domain.text,
                "unit": p.unit,
                "description": p.description,
                **({"value": variant.values[p.name]} if p.name in variant.values else {}),
            }
            for p in variant.scene.parameters
            if p.name in variant.used_parameters  # an option may leave one out
        },
        "options": dict(variant.options),
        "dof": bodies["dof"],
        "constraints": bodies["constraints"],
        "transformation": bodies["transformation"],
        "T": bodies["T"],
        "V": bodies["V"],
        "L": text(variant.lagrangian),
        **nonconservative,
        "momenta": {
            f"p_{q}": text(p)
            for q, p in zip(variant.coordinates, system.generalized_momenta, strict=True)
        },
        "eom": [text(e) for e in system.euler_lagrange],
        "cyclic": list(system.cyclic_coordinates),
        "conserved": {k: text(v) for k, v in system.conserved_quantities.items()},
        "quantities": {k: text(v) for k, v in variant.quantities.items()},
        "phase_space": phase_data(variant),
    }


def solution_json(variant: SceneVariant) -> str:
    return json.dumps(solution_data(variant), indent=2, ensure_ascii=False, sort_keys=False)


def solution_text(variant: SceneVariant) -> str:
    """A readable summary for a terminal."""
    d = solution_data(variant)
    lines = [
        f"{d['title']} ({d['id']}" + (f", seed {d['seed']})" if d["seed"] is not None else ")"),
        "",
    ]
    lines += [d["statement"], ""]
    lines.append("coordinates: " + ", ".join(d["coordinates"]))
    lines.append(
        "parameters:  "
        + ", ".join(
            f"{n} {p['domain']}" + (f" = {p['value']} {p['unit']}".rstrip() if "value" in p else "")
            for n, p in d["parameters"].items()
        )
    )
    if d["options"]:
        lines.append("options:     " + ", ".join(f"{k}={v}" for k, v in d["options"].items()))
    if d["dof"] is None:
        lines += ["given by its Lagrangian (no bodies: no constraints, DOF, T or V)", ""]
        lines += [f"L = {d['L']}", ""]
    else:
        k = len(d["constraints"])
        lines.append(f"DOF:         {d['dof']}  (3N - k with k = {k} constraint{'s' * (k != 1)})")
        lines.append("transformation:")
        lines += [f"  {k} = {v}" for k, v in d["transformation"].items()]
        lines += ["", f"T = {d['T']}", f"V = {d['V']}", f"L = {d['L']}", ""]
    if "dissipation" in d:
        lines.insert(-1, f"F = {d['dissipation']}  (Rayleigh's dissipation function)")
        lines[-1:-1] = [f"Q_{q} = {f}  (generalized force)" for q, f in d["forces"].items()]
    lines += [f"{k} = {v}" for k, v in d["momenta"].items()]
    lines.append(
        "equations of motion (each = 0"
        + (": E_j + dF/dq_j_dot - Q_j)" if "dissipation" in d else ")")
        + ":"
    )
    lines += [f"  {e} = 0" for e in d["eom"]]
    lines.append("cyclic: " + (", ".join(d["cyclic"]) or "none"))
    lines.append("conserved:" + ("" if d["conserved"] else " none"))
    energy = f"{energy_function_name(variant)} (energy function)"
    lines += [f"  {energy if k == 'h' else k} = {v}" for k, v in d["conserved"].items()]
    if d["quantities"]:
        lines.append("quantities:")
        lines += [f"  {k} = {v}" for k, v in d["quantities"].items()]
    lines += ["", *phase_lines(variant)]  # the next lecture: H, Hamilton, small oscillations
    return "\n".join(lines)


def solution_latex(variant: SceneVariant) -> str:
    """The solution as a LaTeX fragment (align environments), dots over velocities."""
    names = latex_symbol_names(variant)

    def tex(e: sp.Expr) -> str:
        return sp.latex(e, symbol_names=names)

    system = variant.system
    out = [f"% {variant.scene.title} ({variant.scene.id})", "\\begin{align*}"]
    if not variant.scene.given_by_lagrangian:
        out.append(f"T &= {tex(variant.kinetic_energy)} \\\\")
        out.append(f"V &= {tex(variant.potential_energy)} \\\\")
    out.append(f"L &= {tex(variant.lagrangian)} \\\\")
    for j, p in zip(variant.jets, system.generalized_momenta, strict=True):
        out.append(f"p_{{{sp.latex(j.q)}}} &= {tex(p)} \\\\")
    for e in system.euler_lagrange:
        out.append(f"0 &= {tex(e)} \\\\")
    for k, v in system.conserved_quantities.items():
        label = energy_function_name(variant) if k == "h" else f"p_{{{k[2:]}}}"
        out.append(f"{label} &= {tex(v)} = \\text{{const}} \\\\")
    out[-1] = out[-1].removesuffix(" \\\\")
    out.append("\\end{align*}")
    cyclic = ", ".join(variant.cyclic_coordinates) or "none"
    if variant.scene.given_by_lagrangian:
        out.append(f"Cyclic coordinates: {cyclic}.")
    else:
        out.append(f"Degrees of freedom: {variant.dof}. Cyclic coordinates: {cyclic}.")
    return "\n".join(out)
