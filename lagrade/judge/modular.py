"""Exact identity of two compiled expressions by arithmetic modulo large primes: the first stage of
the default method (`adaptive.ExactThenAdaptive`) for rational functions of the symbols and of
sin, cos, tan, cot, sec, csc of rational combinations of them (plus multiples of π/2).

Why it is exact: every trig function of Σ r_j x_j + kπ/2 is a polynomial in e^{±i y_j} with
x_j = L_j y_j (L_j the lcm of x_j's denominators), and the Weierstrass substitution
e^{i y} = (1 − u² + 2iu)/(1 + u²) makes it a rational function of u = tan(y/2). A symbol inside
and outside trig functions gets independent values for y and u (y and e^{iy} are algebraically
independent), and so does π outside them. The difference of the two expressions is then a
rational function R of independent variables, and R ≡ 0 exactly when it vanishes at a random
point — with probability of error at most deg R / p (Schwartz–Zippel) — and a random point
modulo a prime p of 61 bits is as good as a random rational one, at a fraction of the cost:
numbers never grow, and sin(10⁶ y) is twenty squarings. With p ≡ 3 (mod 4), −1 is no square,
so 1 + u² never vanishes and the Gaussian numbers mod p form a field.

Two primes, chosen from a table by a digest of the pair, must both agree: a wrong answer that
vanishes modulo both would differ from the reference by a multiple of their product — a
difference of 122 bits built on purpose, invisible to the float stage before this one only when
tiny, so an answer that is the reference plus a term of no size. The degree of R is bounded
before anything is computed (`MAX_DEGREE`), so that the bound on the error stays small; a pair
beyond it, or outside the class, is left to the high-precision stage (None)."""

from __future__ import annotations

import math
import random
import zlib
from fractions import Fraction

from lagrade.judge.evaluate.program import PI, Program

#: Primes p ≡ 3 (mod 4) just below 2^61.
PRIMES = (
    2305843009213693951, 2305843009213693907, 2305843009213693723, 2305843009213693487,
    2305843009213693123, 2305843009213692967, 2305843009213692799, 2305843009213692671,
    2305843009213692527, 2305843009213692463, 2305843009213692427, 2305843009213692419,
    2305843009213692343, 2305843009213692331, 2305843009213692283, 2305843009213692211,
    2305843009213692199, 2305843009213692139, 2305843009213692107, 2305843009213692103,
    2305843009213692083, 2305843009213692043, 2305843009213692031, 2305843009213692007,
    2305843009213691819, 2305843009213691767, 2305843009213691579, 2305843009213691567,
    2305843009213691551, 2305843009213691347, 2305843009213691287, 2305843009213690907,
)  # fmt: skip
#: The largest degree of the difference the test takes: an error has probability at most
#: 2^32 / 2^61 per prime, and both primes must err.
MAX_DEGREE = 2**32
#: Points tried per prime before a side that is undefined at all of them is taken as undefined
#: everywhere (a denominator that vanishes identically).
TRIES = 3

_TRIG = frozenset({"sin", "cos", "tan", "cot", "sec", "csc"})


class _OutOfScope(Exception):
    pass


class _Undefined(Exception):
    """A division by zero modulo p at this point."""


def identical(pair: Program, seed: int = 0) -> bool | None:
    """Whether the pair's first two outputs are the same function (exactly, see the module);
    None when the pair is outside the class this test decides."""
    try:
        plan = _plan(pair)
    except _OutOfScope:
        return None
    digest = zlib.crc32(_fingerprint(pair).encode()) ^ seed
    first = digest % len(PRIMES)
    second = (first + 1 + (digest >> 8) % (len(PRIMES) - 1)) % len(PRIMES)
    rng = random.Random(digest)
    for p in (PRIMES[first], PRIMES[second]):
        verdict = _compare(pair, plan, p, rng)
        if verdict is not True:
            return verdict
    return True


def _fingerprint(program: Program) -> str:
    """The program as text (symbols by name), the same in every process (unlike hash())."""
    return ";".join(
        f"{instr[0]}:{getattr(instr[1], 'name', instr[1]) if instr[0] == 'in' else instr[1:]}"
        for instr in program.code
    )


# --- what the pair needs: trig arguments as integer combinations, the degree ---------------------


class _Plan:
    """For each trig instruction, its argument as {symbol: integer multiple} of the unit angle
    y_s = x_s / L_s and a multiple k of π/2; which symbols carry angles."""

    def __init__(self):
        self.angles: dict[int, tuple[dict, int]] = {}
        self.angle_symbols: set = set()


def _plan(program: Program) -> _Plan:
    forms: dict[int, dict | None] = {}
    code = program.code
    plan = _Plan()
    trig_forms: dict[int, dict] = {}
    for k, instr in enumerate(code):
        op = instr[0]
        if op == "const":
            if not (isinstance(instr[1], Fraction) or instr[1] is PI):
                raise _OutOfScope
        elif op == "fn":
            if instr[1] not in _TRIG:
                raise _OutOfScope
            form = _linear(code, instr[2], forms)
            if form is None or form.get(1, 0) != 0:
                raise _OutOfScope  # a non-linear argument, or a constant term (sin(x + 1))
            half_turns = form.get(PI, Fraction(0)) * 2
            if half_turns.denominator != 1:
                raise _OutOfScope  # sin(x + pi/3): an irrational number
            trig_forms[k] = {s: c for s, c in form.items() if s not in (1, PI)}
            plan.angles[k] = ({}, int(half_turns) % 4)
        elif op not in ("in", "add", "mul", "powi"):
            raise _OutOfScope
    units: dict = {}
    for form in trig_forms.values():
        for s, c in form.items():
            units[s] = math.lcm(units.get(s, 1), c.denominator)
    for k, form in trig_forms.items():
        multiples = plan.angles[k][0]
        for s, c in form.items():
            n = c * units[s]
            multiples[s] = int(n)
            plan.angle_symbols.add(s)
    degree = _degree(program, plan)
    if degree > MAX_DEGREE:
        raise _OutOfScope
    return plan


def _linear(code, k: int, forms: dict) -> dict | None:
    """Instruction k as a linear form {symbol | PI | 1: Fraction}, or None when it is not one."""
    if k in forms:
        return forms[k]
    instr = code[k]
    op = instr[0]
    form: dict | None
    if op == "in":
        form = {instr[1]: Fraction(1)}
    elif op == "const":
        form = {PI: Fraction(1)} if instr[1] is PI else {1: instr[1]}
    elif op == "add":
        form = {}
        for j in instr[1]:
            part = _linear(code, j, forms)
            if part is None:
                form = None
                break
            for key, c in part.items():
                form[key] = form.get(key, 0) + c
    elif op == "mul":
        scale, varying = Fraction(1), None
        for j in instr[1]:
            part = _linear(code, j, forms)
            if part is None:
                varying, scale = None, None
                break
            if set(part) == {1}:
                scale *= part[1]
            elif varying is None:
                varying = part
            else:  # ω t: a monomial argument, left to the high-precision stage
                varying, scale = None, None
                break
        if scale is None:
            form = None
        elif varying is None:
            form = {1: scale}
        else:
            form = {key: c * scale for key, c in varying.items()}
    elif op == "powi":
        base = _linear(code, instr[1], forms)
        form = {1: base[1] ** instr[2]} if base is not None and set(base) == {1} else None
    else:
        form = None
    forms[k] = form
    return form


def _degree(program: Program, plan: _Plan) -> int:
    """A bound on the degree (numerator and denominator) of each output as a rational function
    of the independent variables, summed over the outputs compared."""
    degrees: list[int] = []
    for k, instr in enumerate(program.code):
        op = instr[0]
        if op == "in":
            d = 1
        elif op == "const":
            d = 1 if instr[1] is PI else 0
        elif op == "add" or op == "mul":
            d = sum(degrees[j] for j in instr[1])
        elif op == "powi":
            d = abs(instr[2]) * degrees[instr[1]]
        else:  # a trig function: (1 + u²)^n below, a polynomial of degree 2n above, twice for tan
            d = 4 * sum(abs(n) for n in plan.angles[k][0].values())
        degrees.append(min(d, MAX_DEGREE + 1))
    return sum(degrees[k] for k in program.outputs[:2])


# --- evaluation modulo p -------------------------------------------------------------------------


def _compare(program: Program, plan: _Plan, p: int, rng: random.Random) -> bool | None:
    """Equal (True) or not (False) at a random point modulo p where both sides are defined; a
    side undefined at every point tried is undefined everywhere: the answer then differs (the
    reference is defined on its domain), and an undefined reference leaves no verdict."""
    answer_undefined = 0
    for _ in range(TRIES):
        try:
            values = _values(program, plan, p, rng)
        except _OutOfScope:
            return None
        a, b = values
        if b is None:
            continue  # the reference has no value here: another point
        if a is None:
            answer_undefined += 1
            continue
        return a == b
    return False if answer_undefined else None


def _values(program: Program, plan: _Plan, p: int, rng: random.Random) -> list:
    """The first two outputs at a random point modulo p (None for one undefined there)."""
    point: dict = {}
    for s in program.symbols:
        point[s] = rng.randrange(p)
    turns: dict = {}  # e^{i y_s} as (cos, sin) modulo p
    for s in plan.angle_symbols:
        u = rng.randrange(p)
        inverse = pow(1 + u * u, -1, p)
        turns[s] = ((1 - u * u) * inverse % p, 2 * u * inverse % p)
    pi_value = rng.randrange(p)
    vals: list = []
    for k, instr in enumerate(program.code):
        op = instr[0]
        try:
            if op == "in":
                v = point[instr[1]]
            elif op == "const":
                c = instr[1]
                if c is PI:
                    v = pi_value
                else:
                    if c.denominator % p == 0:
                        raise _OutOfScope
                    v = c.numerator * pow(c.denominator, -1, p) % p
            elif op == "add":
                v = sum(_defined(vals[j]) for j in instr[1]) % p
            elif op == "mul":
                v = 1
                for j in instr[1]:
                    v = v * _defined(vals[j]) % p
            elif op == "powi":
                base = _defined(vals[instr[1]])
                if instr[2] < 0 and base == 0:
                    raise _Undefined
                v = pow(base, instr[2], p)
            else:
                v = _trig(instr[1], plan.angles[k], turns, p)
        except _Undefined:
            v = None
        vals.append(v)
    return [vals[k] for k in program.outputs[:2]]


def _defined(v):
    if v is None:
        raise _Undefined
    return v


#: i^k as (real, imaginary) parts.
_QUARTER_TURNS = ((1, 0), (0, 1), (-1, 0), (0, -1))


def _trig(name: str, angle: tuple[dict, int], turns: dict, p: int) -> int:
    """sin, cos, … of Σ n_s y_s + k π/2 modulo p, from e^{i·argument} = Π (e^{i y_s})^n_s · i^k."""
    multiples, quarter = angle
    re, im = _QUARTER_TURNS[quarter]
    for s, n in multiples.items():
        c, s_ = turns[s]
        if n < 0:  # on the unit circle the inverse is the conjugate
            n, s_ = -n, -s_ % p
        pr, pi_ = _gauss_power(c, s_, n, p)
        re, im = (re * pr - im * pi_) % p, (re * pi_ + im * pr) % p
    re, im = re % p, im % p
    if name == "sin":
        return im
    if name == "cos":
        return re
    numerator, denominator = {"tan": (im, re), "cot": (re, im), "sec": (1, re), "csc": (1, im)}[
        name
    ]
    if denominator == 0:
        raise _Undefined
    return numerator * pow(denominator, -1, p) % p


def _gauss_power(a: int, b: int, n: int, p: int) -> tuple[int, int]:
    """(a + bi)^n modulo p, by repeated squaring."""
    ra, rb = 1, 0
    while n:
        if n & 1:
            ra, rb = (ra * a - rb * b) % p, (ra * b + rb * a) % p
        a, b = (a * a - b * b) % p, (2 * a * b) % p
        n >>= 1
    return ra, rb
