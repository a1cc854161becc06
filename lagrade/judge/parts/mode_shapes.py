"""The `mode_shapes` part: for each normal-mode frequency, its mode vector — the amplitude
ratios of the coordinates, in the order the question lists them — one mode per line:

    omega = sqrt(k/m): (1, 1)
    omega = sqrt(3 k/m): (1, -1)

A line is a frequency (`omega =` optional), a colon, and the vector in brackets. Each vector is
judged up to scale, by physics at every parameter draw: a belongs to the mode of ω when
(K − ω² M) a = 0 (K, M at the key's stable equilibrium, λ = ω² from scipy's `eigh(K, M)`), so a
degenerate pair accepts any vector of its plane. The modes come in any order, each matched to
its frequency (as `normal_modes` matches them); a zero mode (ω = 0) may be left out. Named
mistakes: the shape of another mode (`swapped`), an eigenvector of K alone, the masses left out
(`mass_ignored`), a vector of no mode (`wrong_shape`), the same direction twice for a repeated
frequency (`repeated`), a frequency of no mode, a missing mode."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from lagrade.errors import ParseError, UnsupportedExpression
from lagrade.judge.compiled import to_length
from lagrade.judge.parts.items import Piece, list_items, without_none
from lagrade.judge.parts.oscillation import (
    _SLIPS,
    Quoted,
    _matrices,
    _matrix_at,
    _mode,
    _parameters_only,
    _slip,
    _stable,
    _value_echo,
    oscillation_points,
    quoted_point,
    reference_frequencies,
)
from lagrade.judge.parts.reading import Read, Unreadable, read, read_labelled
from lagrade.judge.problem import Problem
from lagrade.judge.situation import rounded
from lagrade.judge.tolerances import ROUNDING, SAME_FREQUENCY, SAME_MODE
from lagrade.judge.verdict import Verdict, invalid, unreadable_line
from lagrade.mechanics import ZERO_MODE

#: How a line is written, for the messages.
FORMAT = "omega = frequency: (a_1, a_2, …)"
_BRACKETS = (("\\left(", "\\right)"), ("\\left[", "\\right]"), ("(", ")"), ("[", "]"))


@dataclass(frozen=True)
class Mode:
    """One line read: the frequency and the components of its vector."""

    frequency: Read
    vector: tuple[Read, ...]

    @property
    def echo(self) -> str:
        shape = ", ".join(str(c.echo) for c in self.vector)
        return f"omega = {_value_echo(self.frequency)}: ({shape})"


@dataclass(frozen=True)
class ModeLines:
    """The lines of a `mode_shapes` answer, each a Mode or an Unreadable line."""

    entries: tuple[Mode | Unreadable, ...]

    @property
    def modes(self) -> list[Mode]:
        return [e for e in self.entries if isinstance(e, Mode)]

    @property
    def echoes(self) -> list[str]:
        return [e.echo if isinstance(e, Mode) else "" for e in self.entries]

    def feedback(self) -> list[str]:
        return [
            unreadable_line(k + 1, e.error)
            for k, e in enumerate(self.entries)
            if isinstance(e, Unreadable)
        ]


def read_mode_shapes(problem: Problem, answer: Any) -> ModeLines:
    """The modes of an answer, one per item (`items.list_items`: a comma inside the vector's
    brackets never splits); `none` for none. A line that cannot be read is set aside; when no
    line reads, the parser's error is raised (the part is `invalid`)."""
    entries: list[Mode | Unreadable] = []
    for item in without_none(list_items(answer, "mode_shapes")):
        text = str(item)
        try:
            entries.append(_read_mode(problem, text, getattr(item, "latex", False)))
        except ParseError as error:
            entries.append(Unreadable(text, error))
    lines = ModeLines(tuple(entries))
    bad = [e for e in entries if isinstance(e, Unreadable)]
    if bad and not lines.modes:
        if len(bad) == 1:
            raise bad[0].error
        raise ParseError("No line of this answer can be read.\n" + "\n".join(lines.feedback()))
    return lines


def _read_mode(problem: Problem, text: str, latex: bool) -> Mode:
    colon = _top_level_colon(text)
    if colon is None:
        raise ParseError(
            f"Write each mode on its own line as {FORMAT}: the frequency, a colon, and the "
            "amplitudes of the coordinates in brackets.",
            (0, len(text)),
            text,
        )
    head, tail = text[:colon].rstrip(), text[colon + 1 :].rstrip()
    start = colon + 1 + len(tail) - len(tail.lstrip())
    tail = tail.lstrip()
    opening = next((a for a, b in _BRACKETS if tail.startswith(a) and tail.endswith(b)), None)
    if not head.strip() or opening is None:
        raise ParseError(
            f"Write the mode as {FORMAT}, the amplitudes in brackets after the colon.",
            (colon, len(text)),
            text,
        )
    closing = dict(_BRACKETS)[opening]
    inner = tail[len(opening) : len(tail) - len(closing)]
    frequency = _within(text, 0, lambda: read_labelled(problem, Piece(head, latex), ("omega", "w")))
    vector = tuple(
        _within(
            text,
            start + len(opening) + at,
            lambda c=c: read(problem, Piece(c, latex), mode="expression"),
        )
        for at, c in _components(inner)
    )
    return Mode(frequency, vector)


def _within(text: str, offset: int, reading):
    """A piece's reading, its parse error placed in the whole line (the caret under the
    amplitude that does not read, not under a fragment shown alone)."""
    try:
        return reading()
    except ParseError as error:
        if not error.source or error.source not in text:
            raise
        a, b = error.span
        raise ParseError(error.message, (a + offset, b + offset), text, error.hint) from None


def _components(inner: str) -> list[tuple[int, str]]:
    """The vector's entries with their offsets: split at every comma outside brackets (`(3,3)`
    is two entries, not the decimal comma a list's item would be), at no LaTeX command."""
    pieces, depth, start, i = [], 0, 0, 0
    while i < len(inner):
        c = inner[i]
        if c == "\\":
            i += 2
            continue
        if c in "({[":
            depth += 1
        elif c in ")}]":
            depth = max(0, depth - 1)
        elif c == "," and depth == 0:
            pieces.append((start, inner[start:i]))
            start = i + 1
        i += 1
    pieces.append((start, inner[start:]))
    return [(at + len(p) - len(p.lstrip()), p.strip()) for at, p in pieces]


def _top_level_colon(text: str) -> int | None:
    depth = 0
    for i, c in enumerate(text):
        if c in "({[":
            depth += 1
        elif c in ")}]":
            depth = max(0, depth - 1)
        elif c == ":" and depth == 0:
            return i
    return None


def check_mode_shapes(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    _stable(problem, "mode_shapes")
    names = list(problem.coordinates)
    points = oscillation_points(problem)
    ref = reference_frequencies(problem, points)
    top = np.maximum(ref.max(axis=1, keepdims=True), 1e-300)
    modes = [k for k in range(ref.shape[1]) if ref[0, k] > ZERO_MODE * top[0, 0]]
    zero_modes = ref.shape[1] - len(modes)
    lines = read_mode_shapes(problem, answer)
    if not lines.modes:
        if not modes:  # "none": nothing oscillates
            return Verdict("mode_shapes", "correct", 1.0, (), "none", "numeric")
        return invalid("mode_shapes", f"Give each mode on its own line, as {FORMAT}.")
    compiled = _matrices(problem)
    with np.errstate(all="ignore"):
        K = _matrix_at(compiled["K"], points.env, points.n)
        M = _matrix_at(compiled["M"], points.env, points.n)
    size = np.linalg.norm(K, axis=(1, 2)), np.linalg.norm(M, axis=(1, 2))
    feedback, mistakes = lines.feedback(), []
    used = np.zeros(ref.shape, dtype=bool)
    right = wrong = 0
    quoted: Quoted | None = None  # where a sentence quotes frequencies
    accepted: list[tuple[np.ndarray, np.ndarray]] = []  # (a, λ) of each mode credited

    def fits_at(a: np.ndarray, lam: np.ndarray) -> np.ndarray:
        """(K − λ M) a = 0 at each point, relative to the terms' size."""
        r = np.einsum("pij,pj->pi", K - lam[:, None, None] * M, a)
        scale = (size[0] + np.abs(lam) * size[1]) * np.linalg.norm(a, axis=1)
        return np.linalg.norm(r, axis=1) <= SAME_MODE * scale

    def fits(a: np.ndarray, lam: np.ndarray) -> bool:
        return bool(np.all(fits_at(a, lam)))

    def other_mode(a: np.ndarray, lam: np.ndarray) -> int | None:
        """The mode (at the first point) whose shape `a` is at every point, of a frequency
        other than λ's: matched point by point, as the frequencies' order changes between
        draws; None when at some point it is no other mode's shape."""
        found = np.zeros(points.n, dtype=bool)
        first = None
        for j in modes:
            other = np.abs(ref[:, j] ** 2 - lam) > SAME_FREQUENCY * np.abs(lam)
            here = other & fits_at(a, ref[:, j] ** 2)
            if first is None and here[0]:
                first = j
            found |= here
        return first if np.all(found) else None

    for mode in lines.modes:
        if len(mode.vector) != len(names):
            return invalid(
                "mode_shapes",
                f"{mode.echo}: give one amplitude per coordinate, in the order "
                f"({', '.join(names)}).",
                lines.echoes,
            )
        _parameters_only(problem, mode.frequency, "A frequency")
        for c in mode.vector:
            _parameters_only(problem, c, "An amplitude")
        try:
            with np.errstate(all="ignore"):
                w = np.asarray(
                    to_length(mode.frequency.compiled.values(points.env)[0], points.n), complex
                )
                a = np.stack(
                    [
                        np.asarray(to_length(c.compiled.values(points.env)[0], points.n), complex)
                        for c in mode.vector
                    ],
                    axis=1,
                )
        except UnsupportedExpression as error:
            return invalid("mode_shapes", f"Cannot evaluate your answer: {error}.", lines.echoes)
        if not (np.all(np.isfinite(a)) and np.all(np.abs(a.imag) <= ROUNDING * np.abs(a).max())):
            feedback.append(f"{mode.echo}: the amplitudes must be real numbers.")
            wrong += 1
            continue
        a = a.real
        if np.any(np.linalg.norm(a, axis=1) == 0):
            feedback.append(f"{mode.echo}: the zero vector is no mode; give the amplitudes' ratio.")
            mistakes.append("zero_vector")
            wrong += 1
            continue
        if np.all(np.abs(w) <= ROUNDING * top[:, 0]):
            if zero_modes and fits(a, np.zeros(points.n)):
                continue  # the free direction of a zero mode: true, and not required
            feedback.append(f"{mode.echo}: this is no zero mode of this system.")
            mistakes.append("zero_mode")
            wrong += 1
            continue
        before = used.copy()
        if not _mode(w, ref, modes, used):
            wrong += 1
            kind = _slip(w, ref, modes)
            if not kind:
                quoted = quoted or quoted_point(problem, points)
            why = _SLIPS[kind] if kind else _no_frequency(quoted)
            feedback.append(f"{mode.echo}: {why}")
            mistakes.append(kind or "not_a_frequency")
            continue
        k = np.argmax(used & ~before, axis=1)
        lam = ref[np.arange(points.n), k] ** 2
        if fits(a, lam):
            if _dependent(a, [b for b, other in accepted if np.allclose(other, lam)]):
                used[np.arange(points.n), k] = False  # a degenerate pair needs two directions
                feedback.append(
                    f"{mode.echo}: this frequency's other vector already points this way; a "
                    "repeated frequency has a plane of modes, so give two independent vectors."
                )
                mistakes.append("repeated")
                wrong += 1
                continue
            accepted.append((a, lam))
            right += 1
            continue
        wrong += 1
        other = other_mode(a, lam)
        if other is not None:
            quoted = quoted or quoted_point(problem, points)
            feedback.append(f"{mode.echo}: {_swapped(mode, quoted)}")
            mistakes.append("swapped")
        elif _eigenvector_of_K(K, a) and not any(fits_at(a, ref[:, j] ** 2)[0] for j in modes):
            # K's eigenvector that is no mode's shape: so the masses were left out
            feedback.append(
                f"{mode.echo}: this is an eigenvector of K alone; the modes solve "
                "K a = ω² M a, with the mass matrix M."
            )
            mistakes.append("mass_ignored")
        else:
            feedback.append(f"{mode.echo}: (K − ω² M) a ≠ 0, so this is not the mode's shape.")
            mistakes.append("wrong_shape")
    missing = len(modes) - right
    if missing and not wrong:
        noun = "mode is" if missing == 1 else "modes are"
        feedback.append(f"{missing} normal {noun} missing ({len(modes)} in all).")
        mistakes.append("missing_mode")
    correct = right == len(modes) and not wrong and not feedback
    return Verdict(
        "mode_shapes",
        "correct" if correct else "incorrect",
        1.0 if correct else right / max(len(modes), right + wrong),
        tuple(feedback),
        lines.echoes,
        "numeric",
        witness=quoted.witness if quoted else None,
        mistakes=tuple(mistakes),
    )


def _no_frequency(quoted: Quoted) -> str:
    return (
        f"this is not a normal-mode frequency ({quoted.where}, the frequencies are "
        f"{quoted.shown()} rad/s)."
    )


def _swapped(mode, quoted: Quoted) -> str:
    """The vector is another mode's shape (at every point drawn): said with that mode's ω and
    the ω the line gives, both where `quoted` says, found there by (K − ω² M) a = 0; without
    numbers when the shape cannot be placed there."""

    def at(c) -> float:
        return float(np.real(to_length(c.compiled.values(quoted.env)[0], 1)[0]))

    with np.errstate(all="ignore"):
        a, given = np.array([at(c) for c in mode.vector]), at(mode.frequency)
    scale = np.linalg.norm(quoted.K) + np.linalg.norm(quoted.M)
    for w in quoted.frequencies():
        residual = np.linalg.norm((quoted.K - w**2 * quoted.M) @ a)
        if residual <= SAME_MODE * scale * max(w**2, 1.0) * np.linalg.norm(a) and np.isfinite(
            given
        ):
            return (
                f"this is the shape of the mode at ω = {rounded(float(w))} rad/s, not of "
                f"ω = {rounded(given)} ({quoted.where})."
            )
    return "this is the shape of another mode, not of the one at the frequency you give."


def _dependent(a: np.ndarray, others: list[np.ndarray]) -> bool:
    """Whether `a` lies in the span of `others` (vectors already credited to the same
    frequency) at every point: no new direction of a degenerate mode's plane."""
    if not others:
        return False
    stacked = np.stack([*others, a], axis=1)  # (points, vectors, n)
    rank = [np.linalg.matrix_rank(m, tol=SAME_MODE * np.abs(m).max()) for m in stacked]
    return all(r < stacked.shape[1] for r in rank)


def _eigenvector_of_K(K: np.ndarray, a: np.ndarray) -> bool:
    """K a ∥ a at every point (the eigenproblem of K alone, M forgotten)."""
    Ka = np.einsum("pij,pj->pi", K, a)
    mu = np.einsum("pi,pi->p", Ka, a) / np.einsum("pi,pi->p", a, a)
    r = np.linalg.norm(Ka - mu[:, None] * a, axis=1)
    scale = np.linalg.norm(K, axis=(1, 2)) * np.linalg.norm(a, axis=1)
    return bool(np.all(r <= SAME_MODE * scale))


__all__ = ["FORMAT", "Mode", "ModeLines", "check_mode_shapes", "read_mode_shapes"]
