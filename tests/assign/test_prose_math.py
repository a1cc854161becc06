"""Formulas written in prose (statements, quantity and parameter descriptions, prompts) are set
as math in every format: a caret power is a superscript, never a raw `^` that LaTeX's text mode
prints as a circumflex accent (`xˆ2`)."""

from __future__ import annotations

import pickle
import re

import pytest

from lagrade.assign import prose
from lagrade.assign.views import _described, _statement
from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics.scene import SceneVariant


def _all_prose(scene_id: str):
    scene = get_scene(scene_id)
    variant = scene.default
    st = _statement(variant)
    yield st["tex"], st["md"], str(st["html"])
    for text in [p.description for p in scene.parameters] + [
        q.description for q in scene.quantities
    ]:
        rendered = _described(variant, text)
        yield rendered.tex, rendered.md, str(rendered.html)


@pytest.mark.parametrize("scene_id", scene_ids())
def test_no_raw_caret_in_any_prose(scene_id: str) -> None:
    for tex, md, html in _all_prose(scene_id):
        assert "textasciicircum" not in tex, tex
        # a caret may appear only inside $…$ math
        assert "^" not in "".join(md.split("$")[::2]), md
        # nor in what the HTML shows (a formula's aria-label is its plain text, x^2, on purpose)
        shown = re.sub(r"<[^>]*>", "", html)
        assert "^" not in shown, html


def test_free_particle_potential_is_typeset() -> None:
    """The potential comes in through the option's wording, which is prose like the rest."""
    scene = get_scene("free_particle")
    st = _statement(SceneVariant(scene, options={"potential": "anisotropic"}))
    assert "$x^{2}$" in st["tex"] and "$k_{z}$ $z^{2}$" in st["tex"]
    assert "<msup>" in str(st["html"])
    gravity = _statement(SceneVariant(scene, options={"potential": "gravity"}))
    assert "V = $m$ $g$ $z$" in gravity["tex"] and "k" not in gravity["text"].split("V = ")[-1]


def test_hoop_description_sets_omega_squared() -> None:
    variant = get_scene("hoop").default
    (q,) = variant.scene.quantities
    rendered = _described(variant, q.description)
    assert r"$\omega^{2}$ $R$ \textgreater{} $g$" in rendered.tex
    assert "omega^2 R > g" in rendered  # the plain text is unchanged


def test_a_power_after_a_parenthesis_is_a_superscript() -> None:
    rendered = prose.render_prose("V = (x + y)^2")
    assert rendered.tex.endswith(")$^{2}$") and rendered.md.endswith(")²")
    assert str(rendered.html).endswith(")<sup>2</sup>")


def test_prose_survives_pickling() -> None:
    rendered = prose.render_prose("v^2", names=())
    again = pickle.loads(pickle.dumps(rendered))
    assert (again, again.tex, again.md, str(again.html)) == (
        rendered,
        rendered.tex,
        rendered.md,
        str(rendered.html),
    )


def test_a_parameter_named_like_an_english_word_is_math_only_where_it_is_the_name() -> None:
    """`a` and `I` are parameters of some scenes and words of every sentence: "of radius a?" and
    "moment of inertia I about its axle" set the name as math, "a circular orbit" stays prose."""
    kepler = _statement(get_scene("kepler").default)["tex"]
    assert "radius $a$?" in kepler and "round a circular orbit" in kepler
    assert "of a sun" in kepler
    wheel = _statement(get_scene("wheel").default)["tex"]
    assert "inertia $I$ about" in wheel and "on a fixed" in wheel
