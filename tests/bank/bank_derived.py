"""Everything the bank derives, per scene and per presentation (every combination of option
choices and coordinate names), as JSON-ready data: the record that holds the bank's scene files
to what the Python scenes they replaced derived (`test_bank_unchanged.py`).

`python tests/bank/bank_derived.py OUT.json` writes it. The committed record,
`tests/bank/data/bank_derived.json`, was written by this script run against main at b755f21,
the last commit with the Python scenes (`lagrade/bank/scenes/*.py`; first written at c5b4539,
then again at b755f21 once issue 30's figure labels and Markdown prose had landed: only figure
bytes and Markdown statements differ between the two; and again at b755f21 with issue 28's two
presentation changes applied to its code by hand, the figure's axis names in GREY_TEXT and each
MathML formula's aria-label, so only figure bytes and statement HTML differ), and must never be
regenerated from the new code to make a test pass. Only APIs both versions have are used.

One change since, to the SVG hashes alone (round 3, issue 37's label placement): a body's disc or
shape and its mass label carry SVG ids (`body-NAME`, `label-NAME`) in place of matplotlib's
numbered ones. Checked before the 123 hashes were rewritten: with every `<g>` id removed, each
presentation's SVG is byte for byte the one 7ffd123 draws, and every PDF hash is unchanged; no
derivation, statement or PDF entry was touched.

Expressions are kept twice: `str` (readable in a failing diff) and the SHA-256 of `srepr`
(exact: tree shape, argument order and symbol assumptions), so that the record stays small.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import sys
from typing import Any

import sympy as sp


def _expr(e: Any) -> list[str]:
    e = sp.sympify(e) if not isinstance(e, sp.Basic) else e  # numbers the old bank declared
    return [str(e), hashlib.sha256(sp.srepr(e).encode()).hexdigest()[:20]]


def _presentations(scene) -> list[tuple[dict[str, str], dict[str, str]]]:
    """Every (names, options) the scene offers: the product of its renames and option choices."""
    renames = sorted(scene.renames.items())
    options = sorted(scene.options.items())
    out = []
    for names in itertools.product(*[choices for _, choices in renames]):
        for chosen in itertools.product(*[choices for _, choices in options]):
            out.append(
                (
                    dict(zip([c for c, _ in renames], names, strict=True)),
                    dict(zip([o for o, _ in options], chosen, strict=True)),
                )
            )
    return out


def _body(b) -> dict[str, Any]:
    data = {
        "type": type(b).__name__,
        "name": b.name,
        "mass": _expr(b.mass),
        "position": [_expr(x) for x in b.position],
    }
    if hasattr(b, "inertia"):
        data["inertia"], data["angle"] = _expr(b.inertia), _expr(b.angle)
    return data


def presentation(scene, names: dict[str, str], options: dict[str, str], figures: bool) -> dict:
    """What one presentation of a scene derives."""
    from lagrade.assign.views import _statement
    from lagrade.mechanics.scene import SceneVariant

    v = SceneVariant(scene, names=names, options=options)
    v.validate()
    system = v.system
    data: dict[str, Any] = {
        "names": names,
        "options": options,
        "coordinates": list(v.coordinates),
        "statement": v.statement(),
        "statement_fill": v.statement_fill,
        "statement_prose": {k: str(x) for k, x in _statement(v).items()},
        "used_parameters": list(v.used_parameters),
        "dof": v.dof,
        "bodies": [_body(b) for b in v.bodies],
        "constraints": [[label, _expr(f)] for label, f in v.constraints],
        "transformation": {k: _expr(x) for k, x in v.transformation.items()},
        "T": _expr(v.kinetic_energy),
        "V": _expr(v.potential_energy),
        "L": _expr(v.lagrangian),
        "euler_lagrange": [_expr(e) for e in system.euler_lagrange],
        "momenta": [_expr(p) for p in system.generalized_momenta],
        "cyclic": list(system.cyclic_coordinates),
        "conserved": {k: _expr(q) for k, q in system.conserved_quantities.items()},
        "quantities": {k: _expr(q) for k, q in v.quantities.items()},
    }
    if figures:
        from lagrade.assign.figures import draw

        figure = draw(v)
        data["figure"] = {
            "svg": hashlib.sha256(figure.svg).hexdigest(),
            "pdf": hashlib.sha256(figure.pdf).hexdigest(),
        }
    return data


def scene_record(scene, figures: bool = True) -> dict[str, Any]:
    """A scene's declaration, its seeded draws, and every presentation's derivation."""
    return {
        "id": scene.id,
        "title": scene.title,
        "statement": scene.statement,
        "coordinates": list(scene.coordinates),
        "parameters": [
            [p.name, p.domain.text, p.unit, list(p.values), p.description] for p in scene.parameters
        ],
        "renames": {k: list(v) for k, v in scene.renames.items()},
        "options": {k: list(v) for k, v in scene.options.items()},
        "wording": {k: dict(v) for k, v in scene.wording.items()},
        "quantities": [[q.name, q.description, q.unit] for q in scene.quantities],
        "tags": list(scene.tags),
        "draws": [
            [v.names, v.options, v.values] for v in (scene.variant(seed) for seed in range(12))
        ],
        "presentations": [
            presentation(scene, names, options, figures) for names, options in _presentations(scene)
        ],
    }


def bank_record(figures: bool = True) -> dict[str, Any]:
    from lagrade.bank import get_scene, scene_ids

    return {
        "order": scene_ids(),
        "scenes": [scene_record(get_scene(i), figures) for i in scene_ids()],
    }


if __name__ == "__main__":
    record = bank_record()
    with open(sys.argv[1], "w", encoding="utf-8") as f:
        json.dump(record, f, indent=1, sort_keys=True, ensure_ascii=False)
        f.write("\n")
