"""What the templates see: one student's variant of one problem as plain data (statement with
its names set as math, parameters and values, the parts asked with their prompts, the figure),
and the variant's derived solution, computed once per presentation and shared by every seed."""

from __future__ import annotations

import hashlib
import json
import re
from functools import lru_cache
from typing import Any

import sympy as sp
from markupsafe import Markup

from lagrade.assign.assignment import EXPRESSION, AssignedProblem
from lagrade.assign.figures import draw
from lagrade.assign.phase_solution import PHASE_PARTS, PHASE_PROMPTS, phase_solution
from lagrade.assign.prose import Prose, render_prose
from lagrade.assign.solution import energy_function_name
from lagrade.assign.symbols import part_symbols
from lagrade.assign.templating import toml_literal
from lagrade.assign.tidy import tidy
from lagrade.assign.units import Number, unit_formats
from lagrade.assign.variants import VariantChoice
from lagrade.mechanics import LAGRANGIAN_PARTS, RigidBody, Scene, SceneVariant, SpatialRigidBody
from lagrade.notation import key_answer
from lagrade.notation import printer as rm

#: Formulas in prompts are held together: no-break spaces round the signs, and a minus sign
#: (U+2212), not a hyphen, so that no line is broken inside "DOF = 3N − k" or "L = T − V".
PROMPTS: dict[str, str] = {
    "dof": "Count the constraints and give the number of degrees of freedom "
    "(DOF\u00a0=\u00a03N\u00a0\u2212\u00a0k), as a whole number, e.g. 2.",
    "coordinates": "Name the generalized coordinates (use the ones named in the statement).",
    "transformation": "Write the transformation equations: each body's Cartesian coordinates "
    "in terms of the generalized coordinates (and t).",
    "T": "Write the kinetic energy T.",
    "V": "Write the potential energy V.",
    "lagrangian": "Write the Lagrangian L\u00a0=\u00a0T\u00a0\u2212\u00a0V.",
    "eom": "Derive the Euler\u2013Lagrange equations of motion, one per coordinate.",
    "momenta": "Give the generalized momentum of each coordinate.",
    "cyclic": "Which coordinates are cyclic? (Write none if there are none.)",
    "conserved": "Give the conserved quantities as functions of the coordinates and velocities. "
    "(Write none if there are none.)",
    **PHASE_PROMPTS,
}
#: The prompt of a `conserved` part that asks for any one conserved quantity (`all = false`).
ONE_CONSERVED_PROMPT = (
    "Give a conserved quantity (any one) as a function of the coordinates and velocities."
)
#: Parts with a key answer of their own (an expression part's key is its quantity's name).
KEYED_PARTS = tuple(PROMPTS)
#: Parts whose answer sheet field holds several lines (one equation or item per line).
MULTILINE = frozenset(
    {"transformation", "eom", "momenta", "conserved", "hamilton_equations", "mode_shapes"}
)


def _statement(variant: SceneVariant) -> dict[str, Any]:
    """The statement with every coordinate and parameter name set as math, in each format.

    Coordinates enter through the statement's fields (`{theta}`), so a renamed coordinate is set
    as math exactly where the scene put it and nowhere else; prose is searched only for the
    parameters and the coordinates no variant renames (`V = m g z`), as whole words.
    """
    scene = variant.scene
    fixed = {c for c in scene.coordinates if len(scene.renames.get(c, (c,))) == 1}
    st = render_prose(
        scene.statement,
        names=set(variant.parameter_symbols) | fixed,
        fill=variant.statement_fill,
        math_fields=set(scene.coordinates) | set(variant.parameter_symbols),
    )
    return {"text": variant.statement(), "md": st.md, "html": st.html, "tex": st.tex}


def _described(variant: SceneVariant, text: str) -> Prose:
    """A description (of a quantity, a parameter) with its parameter names set as math."""
    return render_prose(text, names=variant.parameter_symbols)


#: Words a description may start with that need no article before it in a sentence.
_DETERMINERS = frozenset({"the", "a", "an", "how", "which", "what", "when", "where", "its"})


def _first_word(text: str) -> str:
    return text.split(maxsplit=1)[0] if text.split() else ""


def _with_article(variant: SceneVariant, description: str) -> str:
    """A quantity's description as the object of "Find …": "angular frequency of small
    oscillations" takes "the"; "the rate lambda …", "how fast …" and a formula's name do not."""
    word = _first_word(description)
    if word.lower() in _DETERMINERS or word in variant.parameter_symbols:
        return description
    return f"the {description}"


def _heading(variant: SceneVariant, description: str) -> str:
    """A description as a heading: its first letter a capital, unless it starts with a name
    (a parameter `m_1` stays as it is)."""
    if _first_word(description) in variant.parameter_symbols:
        return description
    return description[:1].upper() + description[1:]


def _body_kind(body: Any) -> str:
    return "rigid body" if isinstance(body, RigidBody | SpatialRigidBody) else "point mass"


@lru_cache(maxsize=512)
def symbolic_solution(scene: Scene, names: tuple, options: tuple) -> dict[str, Any]:
    """The derived solution of a presentation (names, options) of a scene: it does not depend on
    the parameter values, so every seed with the same names and options shares it. A scene given
    by its Lagrangian has no bodies: no constraints, transformation, T, V or figure."""
    v = SceneVariant(scene, names=dict(names), options=dict(options))
    coords = v.coordinates

    def math(expr: sp.Basic) -> rm.Math:
        return rm.render(expr, coords)

    def eq(lhs: sp.Basic, rhs: sp.Basic) -> rm.Math:
        return rm.equation(lhs, rhs, coords)

    motion = [s for j in v.jets for s in (j.dot, j.ddot)]

    def neat(expr: sp.Expr) -> sp.Expr:
        return tidy(expr, motion)

    system = v.system
    energy = energy_function_name(v)

    def label(name: str) -> sp.Symbol:
        """`p_x_M` → p_{xM}; the energy function `h` renamed when a parameter is called h."""
        if name == "h":
            return sp.Symbol(energy)
        head, _, sub = name.partition("_")
        if head == "p" and sub in coords:  # the printer sets p with the coordinate below it
            return sp.Symbol(name)
        return sp.Symbol(f"{head}_{sub.replace('_', '')}" if sub else head)

    given_l = scene.given_by_lagrangian
    constraints = [
        {
            "description": render_prose(label if label != "declared" else "constraint"),
            "math": eq(f, 0) if f != 0 else None,  # a tilt has no symbol: words alone
        }
        for label, f in ([] if given_l else v.constraints)
    ]
    keyed = [
        p for p in KEYED_PARTS if p not in PHASE_PARTS and (not given_l or p in LAGRANGIAN_PARTS)
    ]
    return {
        "statement": _statement(v),
        "coordinates": [math(sp.Symbol(c)) for c in coords],
        "coordinate_names": list(coords),
        "given_by_lagrangian": given_l,
        "bodies": [
            {"name": b.name, "kind": _body_kind(b), "freedoms": b.freedoms} for b in v.bodies
        ],
        "freedoms": sum(b.freedoms for b in v.bodies),
        "constraints": constraints,
        "k": len(constraints),
        "dof": None if given_l else v.dof,
        "transformation": (
            [] if given_l else [eq(sp.Symbol(k), e) for k, e in v.transformation.items()]
        ),
        "T": None if given_l else math(neat(v.kinetic_energy)),
        "V": None if given_l else math(neat(v.potential_energy)),
        "L": math(neat(v.lagrangian)),
        "momenta": [
            eq(label(f"p_{c}"), neat(p))
            for c, p in zip(coords, system.generalized_momenta, strict=True)
        ],
        "eom": [eq(neat(e), 0) for e in system.euler_lagrange],
        "cyclic": [math(sp.Symbol(c)) for c in system.cyclic_coordinates],
        "cyclic_names": list(system.cyclic_coordinates),
        "conserved": [
            {"name": name, "math": eq(label(name), neat(q))}
            for name, q in system.conserved_quantities.items()
        ],
        "figure": None if given_l else draw(v),
        # the answers as a student types them: the very text the grader checks before it
        # accepts a variant (lagrade.judge.verify), one entry per part the scene can ask
        "key_answers": {
            **{part: key_answer(v, part) for part in keyed},
            **{q: key_answer(v, EXPRESSION, q) for q in v.quantities},
        },
        "variant": v,
    }


def _number(value: sp.Expr) -> str:
    number = complex(sp.N(value, 15))
    if abs(number.imag) > 1e-12 * max(1.0, abs(number.real)):
        return "not real for these values"
    return f"{number.real:.4g}"


def problem_view(problem: AssignedProblem, choice: VariantChoice, name: str) -> dict[str, Any]:
    """Everything a template shows about one student's variant of one problem; `name` is the
    figure's file name (without extension) in the `figures/` folder."""
    scene = problem.scene
    symbolic = symbolic_solution(scene, *presentation(choice))
    variant = choice.variant(scene)
    parameters = _parameters(choice, variant)
    quantities = _quantities(problem, choice, variant)
    parts = _parts(problem, symbolic["variant"])
    phase = _phase(problem, choice)
    return {
        "index": problem.index,
        "title": problem.title,
        "scene": scene.id,
        "seed": choice.seed,
        "statement": symbolic["statement"],
        "coordinates": symbolic["coordinates"],
        "coordinate_names": symbolic["coordinate_names"],
        "parameters": parameters,
        "parts": parts,
        "asked": [p.part for p in problem.parts],
        "total_points": problem.total_points,
        "figure": None
        if symbolic["figure"] is None
        else {
            "svg": f"../figures/{name}.svg",
            "pdf": f"../figures/{name}.pdf",
            "inline_svg": _inline_svg(symbolic["figure"].svg),
            "alt": figure_alternative(problem.index, problem.title, symbolic["figure"].labels),
        },
        "solution": {
            **{
                k: v
                for k, v in symbolic.items()
                if k not in ("figure", "statement", "variant", "key_answers")
            },
            **{k: v for k, v in phase.items() if k != "key_answers"},
            "quantities": quantities,
            "sheet": _sheet(problem, symbolic["key_answers"] | phase.get("key_answers", {})),
        },
    }


def _phase(problem: AssignedProblem, choice: VariantChoice) -> dict[str, Any]:
    """The solution of the parts on phase space and small oscillations, when one is asked."""
    if not any(part.part in PHASE_PARTS for part in problem.parts):
        return {}
    values = tuple(sorted(choice.values.items()))
    return phase_solution(problem.scene, *presentation(choice), values)


def key_answers(problem: AssignedProblem, choice: VariantChoice) -> dict[str, Any]:
    """Every answer of the key as a student types it, by part (by quantity for an expression
    part): the text the grader checks before it accepts a variant."""
    symbolic = symbolic_solution(problem.scene, *presentation(choice))
    return symbolic["key_answers"] | _phase(problem, choice).get("key_answers", {})


def _parameters(choice: VariantChoice, variant: SceneVariant) -> list[dict[str, Any]]:
    """Each parameter the variant uses with its symbol, the student's value (None: stays a
    symbol) and domain."""
    parameters = []
    used = set(variant.used_parameters)
    for p in variant.scene.parameters:
        if p.name not in used:
            continue
        value = choice.values.get(p.name)
        parameters.append(
            {
                "name": p.name,
                "symbol": rm.render(variant.parameter_symbols[p.name]),
                "value": None if value is None else Number(value),
                "unit": p.unit,
                "units": unit_formats(p.unit),
                "description": _described(variant, p.description),
                "domain": p.domain.text,
            }
        )
    return parameters


def _quantities(
    problem: AssignedProblem, choice: VariantChoice, variant: SceneVariant
) -> dict[str, dict[str, Any]]:
    """The quantities the expression parts ask for: closed form, and value at the student's
    parameter values."""
    declared = {q.name: q for q in variant.scene.quantities}
    quantities = {}
    for part in problem.parts:
        if part.part != EXPRESSION:
            continue
        q = declared[part.quantity]
        expr = variant.quantities[q.name]
        quantities[q.name] = {
            "name": q.name,
            "description": _described(variant, q.description),
            "heading": _described(variant, _heading(variant, q.description)),
            "unit": q.unit,
            "units": unit_formats(q.unit),
            "formula": rm.named_equation(q.name, expr, variant.coordinates),
            "value": _number(
                expr.xreplace(
                    {
                        variant.parameter_symbols[n]: sp.Float(v, 15)
                        for n, v in choice.values.items()
                    }
                )
            ),
        }
    return quantities


def _parts(problem: AssignedProblem, variant: SceneVariant) -> list[dict[str, Any]]:
    """The parts asked, each with its prompt, points, unit (numeric follow-ups) and the names
    its answer may use."""
    declared = {q.name: q for q in problem.scene.quantities}
    parts = []
    for part in problem.parts:
        unit = None
        if part.part == EXPRESSION:
            q = declared[part.quantity]
            prompt = _described(
                variant,
                f"Find {_with_article(variant, q.description)}: a closed form in the "
                "parameters (or its value for your parameter values).",
            )
            unit = unit_formats(q.unit) if q.unit else None
        elif part.part == "conserved" and not part.all:
            prompt = render_prose(ONE_CONSERVED_PROMPT)
        else:
            prompt = render_prose(PROMPTS[part.part])
        parts.append(
            {
                "key": part.key,
                "part": part.part,
                "quantity": part.quantity,
                "points": part.points,
                "prompt": prompt,
                "unit": unit,
                "multiline": part.part in MULTILINE,
                "symbols": part_symbols(variant, part.part),
            }
        )
    return parts


def _sheet(problem: AssignedProblem, answers: dict[str, Any]) -> str:
    """The problem's key in the answer sheet's own TOML, as a student would hand it in."""
    lines = [f"[problem{problem.index}]"]
    for part in problem.parts:
        answer = answers[part.quantity if part.part == EXPRESSION else part.part]
        lines.append(f"{part.key} = {toml_literal(answer, part.part in MULTILINE)}")
    return "\n".join(lines)


def figure_alternative(index: int, title: str, labels: tuple[str, ...]) -> str:
    """The figure's text alternative: what it shows and the names written on it, in the
    notation students type (`x_M`, `alpha`); the statement beside it says the rest."""
    names = [
        re.sub(r"\\([A-Za-z]+)", r"\1", t.strip("$")).replace("{", "").replace("}", "")
        for t in labels
    ]
    shown = ", ".join(dict.fromkeys(n for n in names if n))
    return f"Figure of problem {index}, {title}, drawn as the statement describes" + (
        f"; labelled {shown}." if shown else "."
    )


def _inline_svg(svg: bytes) -> Markup:
    text = svg.decode("utf-8")
    return Markup(text[text.index("<svg") :])


def presentation(choice: VariantChoice) -> tuple[tuple, tuple]:
    """The (names, options) of a variant, hashable: the key of its symbolic solution."""
    return tuple(sorted(choice.names.items())), tuple(sorted(choice.options.items()))


def figure_name(problem: AssignedProblem, choice: VariantChoice) -> str:
    """`p<index>-<scene>-<digest of names and options>`: students who share a presentation
    share a figure file."""
    tag = json.dumps([sorted(choice.names.items()), sorted(choice.options.items())])
    digest = hashlib.sha256(tag.encode()).hexdigest()[:10]
    return f"p{problem.index}-{problem.scene_id}-{digest}"
