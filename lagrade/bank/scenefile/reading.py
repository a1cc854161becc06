"""Reading a scene file's expressions with the notation layer (the grammar students' answers go
through: never eval or sympify), and holding each field to the names it may use.

One vocabulary serves the whole file: the coordinates (with their velocities), the parameters as
the very symbols of the variant (their domains as assumptions), `t`, the names the options bind
(`let`), each body's Cartesian coordinates (`x_bead`, `y_bead`, `z_bead`, and `phi_wheel` for a
rigid body) and `gravity`. Which of those a field may use is the field's rule (`ALLOWED`): a
position is written in the coordinates, a potential may add velocities and Cartesian coordinates,
a constraint is written in the Cartesian coordinates.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

import sympy as sp

from lagrade.bank.scenefile.declaration import Declaration, cartesian_axes
from lagrade.bank.scenefile.fields import Problems, Text
from lagrade.errors import LagradeError, ParseError
from lagrade.mechanics import lagrange as mech
from lagrade.notation import Vocabulary, parse_expression

#: What each kind of field may name.
ALLOWED = {
    "body": {"coordinate", "parameter", "time", "let"},
    "potential": {"coordinate", "velocity", "parameter", "time", "let", "cartesian", "gravity"},
    "lagrangian": {"coordinate", "velocity", "parameter", "time", "let"},
    "dissipation": {"coordinate", "velocity", "parameter", "time", "let"},
    "constraint": {"parameter", "time", "let", "cartesian"},
    "let": {"coordinate", "velocity", "parameter", "time"},
    "quantity": {"parameter", "let"},
    "relation": {"parameter"},
    "figure": {"coordinate", "parameter", "time", "let"},
    "state": {"coordinate", "velocity", "parameter", "let", "quantity"},
}
_WHAT = {
    "coordinate": "a coordinate",
    "velocity": "a velocity",
    "acceleration": "an acceleration",
    "parameter": "a parameter",
    "time": "time",
    "let": "a name an option binds",
    "cartesian": "a body's Cartesian coordinate",
    "gravity": "the potential of uniform gravity",
    "quantity": "a quantity",
}
_FIELD = {
    "body": "a body's mass, position, inertia and angle use the coordinates, parameters, t and "
    "the names options bind",
    "potential": "a potential uses the coordinates and velocities, the bodies' Cartesian "
    "coordinates (x_bead, …), gravity, parameters, t and the names options bind",
    "lagrangian": "a Lagrangian uses the coordinates and velocities, parameters and t",
    "dissipation": "a dissipation function or a generalized force uses the coordinates and "
    "velocities, parameters, t and the names options bind",
    "constraint": "a constraint is written in the bodies' Cartesian coordinates (x_bead, …), "
    "parameters and t",
    "let": "a name an option binds is an expression in the coordinates, velocities, parameters "
    "and t",
    "quantity": "a quantity is a closed form in the parameters",
    "relation": "a relation is an inequality between expressions in the parameters",
    "figure": "a figure's expressions use the coordinates, parameters, t and the names options "
    "bind",
    "state": "a state gives coordinates and velocities in the parameters and quantities",
}


def _indented(error: ParseError) -> str:
    """The parser's message with its source line and caret, indented under the key."""
    lines = str(error).split("\n")
    return "\n".join([lines[0], *("      " + line.strip("\n") for line in lines[1:])])


class Reader:
    """Reads every expression of one declaration; problems go to the file's list."""

    def __init__(self, d: Declaration, problems: Problems):
        self.problems = problems
        self.jets = {c: mech.jet(c) for c in d.coordinates}
        self.parameters = {p.name: p.domain.symbol(p.name) for p in d.parameters}
        self.quantities = [q.name for q in d.quantities]
        self.lets = sorted({n for cs in d.options.values() for c in cs for n in c.lets})
        self.cartesians: dict[str, str] = {}  # x_bead → bead
        for body in all_bodies(d):
            for axis in cartesian_axes(body):
                self.cartesians.setdefault(f"{axis}_{body.name}", body.name)
        self.category: dict[str, str] = {"t": "time", "gravity": "gravity"}
        self._clashes(d)
        for j in self.jets.values():
            self.category |= {
                j.name: "coordinate",
                j.dot.name: "velocity",
                j.ddot.name: "acceleration",
            }
        self.category |= {n: "parameter" for n in self.parameters}
        self.category |= {n: "let" for n in self.lets}
        self.category |= {n: "cartesian" for n in self.cartesians}
        labels = [*self.lets, *self.cartesians, "gravity"]
        try:
            self.vocabulary: Vocabulary | None = Vocabulary(
                tuple(self.jets), self.parameters, tuple(labels)
            )
            self.with_quantities = Vocabulary(
                tuple(self.jets), self.parameters, tuple([*labels, *self.quantities])
            )
        except LagradeError:  # a clash the checks above have named already
            self.vocabulary = None
        self.symbols = {s.name: s for s in self._all_symbols()}

    def _all_symbols(self) -> Iterable[sp.Symbol]:
        yield mech.t
        for j in self.jets.values():
            yield from (j.q, j.dot, j.ddot)
        yield from self.parameters.values()
        for name in [*self.lets, *self.cartesians, "gravity", *self.quantities]:
            yield sp.Symbol(name, real=True)

    def _clashes(self, d: Declaration) -> None:
        """Names that would mean two things: a let or a body's Cartesian coordinate named like a
        coordinate or parameter (a body M beside a coordinate x_M), two spellings the reader
        takes for one name (m1 and m_1), a renamed coordinate that is taken."""
        owners: dict[str, str] = {}
        entries = [(c, f"coordinate {c!r}") for c in d.coordinates]
        entries += [(f"{c}_dot", f"the velocity of {c!r}") for c in d.coordinates]
        entries += [(p, f"parameter {p!r}") for p in self.parameters]
        entries += [(n, f"the name {n!r} an option binds") for n in self.lets]
        entries += [
            (n, f"the Cartesian coordinate {n} of body {b!r}") for n, b in self.cartesians.items()
        ]
        entries += [(q, f"quantity {q!r}") for q in self.quantities]
        for name, owner in entries:
            spelled = re.sub(r"_(?=[0-9])", "", name)
            for key in {name, spelled}:
                if key in owners and owners[key] != owner:
                    self.problems.add(
                        "names", f"{owner} and {owners[key]} are one name to the reader"
                    )
                owners.setdefault(key, owner)
        for coordinate, names in d.renames.items():
            for name in names[1:]:
                taken = owners.get(name) or owners.get(re.sub(r"_(?=[0-9])", "", name))
                if taken is not None:
                    self.problems.add(f"renames.{coordinate}", f"{name!r} is already {taken}")

    def read(
        self, text: Text | None, kind: str, bodies: Iterable[str] | None = None
    ) -> sp.Expr | None:
        """The expression `text`, or None with its problem recorded. `bodies` limits which
        bodies' Cartesian coordinates it may name (those present whenever it applies)."""
        if text is None or self.vocabulary is None:
            return None
        vocabulary = self.with_quantities if kind == "state" else self.vocabulary
        try:
            parsed = parse_expression(text.text, vocabulary, latex=None)
        except ParseError as error:
            self.problems.add(text.key, _indented(error))
            return None
        for warning in parsed.warnings:
            self.problems.add(text.key, f"{warning} (a scene file must be unambiguous)")
        expr = parsed.expr
        allowed = ALLOWED[kind]
        seen = False
        for symbol in sorted(expr.free_symbols, key=str):
            category = (
                "quantity" if symbol.name in self.quantities else self.category.get(symbol.name)
            )
            if category not in allowed:
                self.problems.add(
                    text.key,
                    f"uses {symbol.name}, {_WHAT.get(category or '', 'an unknown name')}; "
                    f"{_FIELD[kind]}",
                )
                seen = True
            elif category == "cartesian" and bodies is not None:
                owner = self.cartesians[symbol.name]
                if owner not in bodies:
                    self.problems.add(
                        text.key,
                        f"uses {symbol.name}, but body {owner!r} is not there whenever this "
                        "applies (it belongs to an option's choice)",
                    )
                    seen = True
        return None if seen else expr


def all_bodies(d: Declaration) -> list:
    """The scene's bodies and every option choice's, in the order declared."""
    return [*d.bodies, *(b for cs in d.options.values() for c in cs for b in c.bodies)]
