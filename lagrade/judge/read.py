"""Reading an answer, a step of its own beside judging: what a preview (the answer page's live
"read as", PrairieLearn's `parse`) shows, without deciding whether the answer is right.

Each part reads its answer with the one reader its checker reads it with (`READERS`: the
part's `read_…` function), so a preview never disagrees with a verdict about what was read;
and a reading costs only the parser's work — no reference is derived, no mistake catalogue is
built. Each line keeps the parser's own result, so its typeset form is made from what was read,
never by parsing an echo again.

    Reading(part, status, lines, message, notes)
    status   empty | read | unreadable (no line of the answer can be read)
    lines    one per item read: its plain echo, its MathML (a formula's; "" for a name or a
             number), and the parser's message with its caret for a line that cannot be read
    message  the parser's messages, one per unreadable line, or for the whole answer
    notes    how the parser read what it read (`g/2 l` read as (g/2)·l), whatever the verdict
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from lagrade.errors import ParseError, RequestError
from lagrade.judge.parts.conserved import read_conserved
from lagrade.judge.parts.coordinates import read_coordinates
from lagrade.judge.parts.cyclic import read_cyclic
from lagrade.judge.parts.dof import read_dof
from lagrade.judge.parts.energy import read_kinetic, read_lagrangian, read_potential
from lagrade.judge.parts.eom import read_eom
from lagrade.judge.parts.expression import read_expression
from lagrade.judge.parts.hamilton_equations import read_hamilton_equations
from lagrade.judge.parts.hamiltonian import read_hamiltonian
from lagrade.judge.parts.mode_shapes import ModeLines, read_mode_shapes
from lagrade.judge.parts.momenta import read_momenta
from lagrade.judge.parts.oscillation import read_equilibrium, read_normal_modes
from lagrade.judge.parts.reading import Lines, Read, Unreadable, reading_notes
from lagrade.judge.parts.transformation import read_transformation
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import unreadable_line

#: Each part's reader: the function its checker reads the raw answer with.
READERS: dict[str, Callable[[Problem, Any], Any]] = {
    "dof": read_dof,
    "coordinates": read_coordinates,
    "transformation": read_transformation,
    "lagrangian": read_lagrangian,
    "T": read_kinetic,
    "V": read_potential,
    "eom": read_eom,
    "momenta": read_momenta,
    "cyclic": read_cyclic,
    "conserved": read_conserved,
    "expression": read_expression,
    "hamiltonian": read_hamiltonian,
    "hamilton_equations": read_hamilton_equations,
    "equilibrium": read_equilibrium,
    "normal_modes": read_normal_modes,
    "mode_shapes": read_mode_shapes,
}
#: Parts written on phase space: their formulas are typeset with the momenta as variables
#: (ṗ_θ for p_theta_dot).
ON_PHASE_SPACE = ("hamiltonian", "hamilton_equations")


@dataclass(frozen=True)
class ReadLine:
    """One item of an answer as read: its plain echo and MathML, or the parser's message."""

    plain: str
    mathml: str = ""
    error: str = ""

    def to_dict(self) -> dict[str, str]:
        return {"plain": self.plain, "mathml": self.mathml, "error": self.error}


@dataclass(frozen=True)
class Reading:
    """An answer's structured reading (see the module's docstring)."""

    part: str
    status: str
    lines: tuple[ReadLine, ...] = ()
    message: str = ""
    notes: tuple[str, ...] = ()

    @property
    def unreadable_lines(self) -> list[str]:
        """The parser's message for each line that cannot be read (the answer as a whole when
        it is unreadable)."""
        if self.status == "unreadable":
            return [self.message]
        return [line.error for line in self.lines if line.error]

    def to_dict(self) -> dict[str, Any]:
        return {
            "part": self.part,
            "status": self.status,
            "lines": [line.to_dict() for line in self.lines],
            "message": self.message,
            "notes": list(self.notes),
        }


def read_answer(problem: Problem, part: str, answer: Any) -> Reading:
    """The reading of `answer` to `part` of `problem`: the part's own reader, and nothing else.
    A student's text never raises here; a malformed request (an unknown part, an answer that
    is neither text nor a list of texts) raises RequestError."""
    reader = READERS.get(part)
    if reader is None:
        raise RequestError(f"unknown part {part!r}; parts: {', '.join(READERS)}")
    if _blank(answer):
        return Reading(part, "empty")
    with reading_notes() as notes:
        try:
            got = reader(problem, answer)
        except ParseError as error:
            return Reading(part, "unreadable", message=str(error), notes=tuple(notes))
        lines = tuple(_lines(problem, part, got))
    errors = [line.error for line in lines if line.error]
    return Reading(part, "read", lines, "\n".join(errors), tuple(notes))


def _lines(problem: Problem, part: str, got: Any):
    """The lines of what a reader returned, shown as the part's verdict shows its reading."""
    if isinstance(got, ModeLines):  # a frequency and its vector: the plain echo says both
        for k, entry in enumerate(got.entries):
            if isinstance(entry, Unreadable):
                yield ReadLine("", error=unreadable_line(k + 1, entry.error))
            else:
                yield ReadLine(entry.echo)
    elif isinstance(got, Lines):
        for k, entry in enumerate(got.entries):
            if isinstance(entry, Unreadable):
                yield ReadLine("", error=unreadable_line(k + 1, entry.error))
            else:
                yield _formula(problem, entry, part)
    elif isinstance(got, Read):
        yield _formula(problem, got, part)
    elif isinstance(got, str):  # a number of degrees of freedom
        yield ReadLine(got)
    elif part == "coordinates":
        yield ReadLine(", ".join(name.name for name in got))
    elif part == "cyclic":
        yield from (ReadLine(name.name) for name in got) if got else [ReadLine("none")]
    else:  # expression: a closed form, or `closed form = value`
        yield ReadLine(" = ".join(str(r.echo) for r in got), _joined_mathml(problem, got))


def _formula(problem: Problem, got: Read, part: str = "") -> ReadLine:
    return ReadLine(str(got.echo), _mathml(problem, got, part))


def _mathml(problem: Problem, got: Read, part: str = "") -> str:
    if got.parsed is None:
        return ""
    variables = problem.coordinates
    if part in ON_PHASE_SPACE:
        variables = (*variables, *(f"p_{c}" for c in problem.coordinates))
    return str(got.parsed.mathml(variables))


def _joined_mathml(problem: Problem, reads: list[Read]) -> str:
    if len(reads) == 1:
        return _mathml(problem, reads[0])
    return ""  # a closed form beside its value: each side's plain echo says it


def _blank(answer: Any) -> bool:
    if isinstance(answer, str):
        return not answer.strip()
    if isinstance(answer, list | tuple):
        return not any(isinstance(a, str) and a.strip() for a in answer)
    return answer is None


__all__ = ["READERS", "ReadLine", "Reading", "read_answer"]
