"""Limits against denial of service, all checked before sympy sees anything big (the lexer keeps
its own limits on how a number may be written)."""

MAX_LENGTH = 2_000  # characters per answer
MAX_TOTAL_LENGTH = 20_000  # characters in a list of equations
MAX_DEPTH = 50  # nesting of brackets, signs and powers
MAX_NODES = 2_000  # tree nodes per answer
MAX_EXPONENT = 1_000_000  # |numeric exponent| of a symbolic base: evaluated by repeated squaring
MAX_FUNCTION_POWER = 100  # n in sin^n(x)
MAX_NUMBER_BITS = 4_000  # size of an exact number produced by a power
#: Terms a power of a sum would have once multiplied out, C(n + k - 1, k - 1) for a sum of k
#: terms to the n: what an expansion downstream could cost. (x - b)^5000 has 5,001 and is fine;
#: (a + b + c + d + e)^1000 has 4·10^10 and is refused.
MAX_EXPANDED_TERMS = 1_000_000
#: Arguments of all the Max and Min calls of one answer together: a judge compares them pairwise.
MAX_EXTREMUM_ARGUMENTS = 8
#: Tree nodes a time derivative d/dt(…) may write out: the product rule turns a product of n
#: factors into n products (sympy takes ~0.1 ms a node), and no answer needs more than this.
MAX_DERIVATIVE_NODES = 2_000
