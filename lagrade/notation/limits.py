"""Limits against denial of service, all checked before sympy sees anything big (the lexer keeps
its own limits on how a number may be written)."""

MAX_LENGTH = 2_000  # characters per answer
MAX_TOTAL_LENGTH = 20_000  # characters in a list of equations
MAX_DEPTH = 50  # nesting of brackets, signs and powers
MAX_NODES = 2_000  # tree nodes per answer
MAX_EXPONENT = 100  # |numeric exponent|
MAX_NUMBER_BITS = 4_000  # size of an exact number produced by a power
