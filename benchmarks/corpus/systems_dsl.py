"""A few words for writing the systems corpus (systems.jsonl) by hand: a System holds one
mechanical system from a public source — its reference Lagrangian, coordinates and parameters —
and the answers written to it, each with its label and its `meaning` in sympy syntax (what the
answer says, for verify_systems.py, which never asks lagrade).

    s = System("ll_5_1_double_pendulum", SOURCE, "…", ["phi1", "phi2"], {"m1": "positive", …})
    s.ok("lagrangian", "½(m1+m2) l1² φ1̇² + …", meaning="…", form="unicode_expanded")
    s.bad("eom", ["…", "…"], meaning=[…], mistake="missing_cross_term")
    e = s.expression("2*pi*sqrt(l/g)", {"l": "positive", "g": "positive"})
    e.ok("2 pi sqrt(l/g)", form="plain")

A meaning left out is the answer itself, which must then be sympy syntax (explicit * and **):
the verifier refuses anything else, so a missing meaning cannot silently mean another thing.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

#: The classes of mistake a wrong answer may carry.
MISTAKES = {
    "sign_of_V": "the potential energy added instead of subtracted (L = T + V)",
    "v_minus_t": "L = V − T: the right dynamics in the wrong convention",
    "missing_cross_term": "a product of two velocities (or velocity × support motion) left out",
    "factor_2": "a factor 2 lost or doubled",
    "wrong_moment_of_inertia": "a moment of inertia (or an l vs l²) that is not the body's",
    "missing_centripetal": "a centripetal/centrifugal term (r θ̇², ω² term) left out",
    "forgot_constraint": "a constraint not used: a coordinate's motion left out of T or V",
    "wrong_chain_rule": "d/dt of a coordinate-dependent factor done wrong (a q̇ or a term lost)",
    "wrong_sign": "one term with the wrong sign",
    "wrong_trig": "sin where cos belongs (or the reverse): the angle measured from the other axis",
    "missing_term": "a term of the answer left out",
    "not_conserved": "a quantity that is not conserved along the motion",
    "constant": "a constant offered as a conserved quantity",
    "not_independent": "conserved quantities that are one quantity (a parameter multiple)",
    "not_cyclic": "a coordinate that L depends on named cyclic",
    "missed_cyclic": "a cyclic coordinate left out",
    "kinetic_momentum": "m v given where the canonical momentum has a vector-potential term",
    "other_lagrangian": "what belongs to another equivalent Lagrangian, not the given one",
    "nonrelativistic": "the Newtonian limit given for a relativistic quantity",
    "small_angle": "the small-angle approximation where the exact equation is asked",
    "wrong_expression": "a closed form with a slip (inverted ratio, wrong power, missing factor)",
    "too_few_equations": "fewer equations than coordinates",
    "swapped_parameter": "two parameters interchanged (m1 where m2 belongs)",
}

_GREEK = {
    "theta": "θ",
    "phi": "φ",
    "psi": "ψ",
    "omega": "ω",
    "Omega": "Ω",
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "mu": "μ",
    "rho": "ρ",
    "lambda": "λ",
    "pi": "π",
}


def uni(text: str) -> str:
    """The Unicode spelling a student types from a phone or a symbol palette: Greek letters,
    dots over single-letter velocities, ², ³, · and ½."""

    def name(match: re.Match) -> str:
        word = match.group(0)
        for suffix, mark in (("_ddot", "\u0308"), ("_dot", "\u0307")):
            if word.endswith(suffix):
                base = word[: -len(suffix)]
                shown = _GREEK.get(base, base)
                if len(shown) == 1:
                    return shown + mark
                return _GREEK.get(base, base) + suffix
        return _GREEK.get(word, word)

    out = re.sub(r"[A-Za-z][A-Za-z0-9_]*", name, text)
    out = re.sub(r"\^2(?![0-9])", "²", out)
    out = re.sub(r"\^3(?![0-9])", "³", out)
    out = out.replace("1/2 ", "½ ").replace(" * ", "·").replace("*", "·")
    return out


def notation_of(answer: str | list[str]) -> str:
    text = "".join(answer) if isinstance(answer, list) else answer
    if "\\" in text:
        return "latex"
    if any(ord(c) > 127 for c in text):
        return "unicode"
    return "plain"


@dataclass
class Case:
    """One labelled answer, as stored in systems.jsonl."""

    id: str
    system: str
    problem: dict
    part: str
    answer: str | list[str]
    label: str
    meaning: str | list[str]
    mistake: str | None
    form: str
    source: str
    given: dict | None = None

    def record(self) -> dict[str, Any]:
        request: dict[str, Any] = {"problem": self.problem, "part": self.part}
        request["answer"] = self.answer
        if self.given is not None:
            request["given"] = self.given
        return {
            "id": self.id,
            "system": self.system,
            "request": request,
            "label": self.label,
            "mistake": self.mistake,
            "form": self.form,
            "notation": notation_of(self.answer),
            "meaning": self.meaning,
            "source": self.source,
        }


@dataclass
class _Question:
    key: str
    source: str
    problem: dict
    cases: list[Case] = field(default_factory=list)

    def _add(self, part, answer, meaning, label, mistake, form, given) -> Case:
        if meaning is None:
            meaning = answer
        if label == "incorrect" and mistake not in MISTAKES:
            raise ValueError(f"{self.key}: unknown mistake class {mistake!r}")
        tag = re.sub(r"[^a-z0-9]+", "_", (form if label == "correct" else mistake).lower())
        base = f"{self.key}/{part}/{'ok' if label == 'correct' else 'bad'}-{tag.strip('_')}"
        taken = {c.id for c in self.cases}
        case_id, n = base, 2
        while case_id in taken:
            case_id, n = f"{base}-{n}", n + 1
        case = Case(
            case_id,
            self.key.split("/")[0],
            self.problem,
            part,
            answer,
            label,
            meaning,
            mistake,
            form,
            self.source,
            given,
        )
        self.cases.append(case)
        return case

    def ok(self, part, answer, meaning=None, form="plain", given=None) -> Case:
        return self._add(part, answer, meaning, "correct", None, form, given)

    def bad(self, part, answer, meaning=None, mistake="", given=None, form="") -> Case:
        return self._add(part, answer, meaning, "incorrect", mistake, form, given)


class ExpressionQuestion(_Question):
    """A closed-form (or numeric) result of a system: {"expression", "parameters"}."""

    def ok(self, answer, meaning=None, form="plain") -> Case:  # type: ignore[override]
        return super().ok("expression", answer, meaning, form)

    def bad(self, answer, meaning=None, mistake="wrong_expression") -> Case:  # type: ignore[override]
        return super().bad("expression", answer, meaning, mistake)


class System(_Question):
    """A mechanical system given by its Lagrangian: parts lagrangian, eom, momenta, cyclic,
    conserved on it, and expression questions about its results."""

    def __init__(
        self,
        key: str,
        source: str,
        lagrangian: str,
        coordinates: list[str] | dict[str, str | None],
        parameters: dict[str, str],
    ):
        problem = {"lagrangian": lagrangian, "coordinates": coordinates, "parameters": parameters}
        super().__init__(key, source, problem)
        self.expressions: list[ExpressionQuestion] = []

    def expression(
        self, reference: str, parameters: dict[str, str], name: str, source: str | None = None
    ) -> ExpressionQuestion:
        question = ExpressionQuestion(
            f"{self.key}/{name}",
            source or self.source,
            {"expression": reference, "parameters": parameters},
        )
        self.expressions.append(question)
        return question

    def all_cases(self) -> list[Case]:
        return self.cases + [c for e in self.expressions for c in e.cases]
