"""Every tolerance the judge uses, named once, each with what it compares and why it is that
size: a reader finds here what "equal", "zero", "the same factor" and "full rank" mean, and a
change to one is a change in one place. Relative tolerances are ratios to the size of what is
compared (the sum of the absolute values of the terms, or 1 + |value| where a value may be 0).

The decision every equivalence test ends in (`lagrade.judge.decision`):
"""

#: Below this ratio of residual to term size two answers agree in float64 (a float64 sum of n
#: terms carries about n·1e-16 of rounding: ample room below).
EQUAL_BELOW = 1e-10
#: Above it they differ; in between, 50-digit arithmetic decides.
DIFFERENT_ABOVE = 1e-6
#: The 50-digit decision: equal below this ratio.
MP_EQUAL_BELOW = 1e-30

#: The mistake catalogue's fingerprints: a mistake whose E is this close to a multiple of the
#: reference's (relative to its terms) is tested for the same dynamics the symbolic way;
#: farther ones are different by every test (DIFFERENT_ABOVE, with a margin for sizes summed in
#: another order) ...
SAME_DYNAMICS_SUSPECT = 1e-4
#: ... and this close is the same dynamics by every test (below EQUAL_BELOW).
SURE_EQUAL = 1e-12

# --- values computed two ways -------------------------------------------------------------------

#: Two float64 values of one quantity computed by different routes (a recovered constant, a
#: value recognised as a fraction of π, a point mapped back): equal within this relative
#: difference.
SAME_VALUE = 1e-9
#: A factor or ratio fitted by least squares from float64 values (c in L′ = c L, a mutant's
#: coefficient): the same at every point within this relative difference.
SAME_FACTOR = 1e-8
#: What is exactly zero in exact arithmetic reads below this relative size in float64 (an
#: imaginary part of a real value, a coefficient that cancels, a score that is 1).
ROUNDING = 1e-12

#: Two mistakes' fingerprints closer than this share of their size are screened as one before
#: they are compared exactly.
NEAR_DUPLICATE = 1e-6

# --- linear algebra ------------------------------------------------------------------------------

#: A singular value counts toward a rank when above this share of the largest.
RANK = 1e-8
#: The mass matrix is singular at a point where its determinant is below this share of the
#: product of its rows' norms (a point where the motion is not determined is not sampled).
SINGULAR_MASS = 1e-6
#: A conserved quantity is a constant when its gradient on phase space is below this share of
#: its size at every point.
CONSTANT_GRADIENT = 1e-10
#: An equation's residual row is zero below this share of its size (an identity, not an
#: equation of motion).
ZERO_ROW = 1e-10

#: Normal-mode frequencies agree within this fraction (the reference is scipy's generalized
#: eigensolver's, in float64).
SAME_FREQUENCY = 1e-8
#: A mode vector a belongs to the frequency ω when |(K − ω² M) a| is below this fraction of
#: (|K| + ω² |M|) |a| (both matrices and ω² in float64: a few ulps of each term's size).
SAME_MODE = 1e-7
#: A Hamiltonian matches a catalogued mistake within this fraction of its terms' size (the
#: momenta it is evaluated at are solved in float64, one step more than an L's values).
H_MATCH = 1e-7

# --- the student's numbers -----------------------------------------------------------------------

#: A number typed in an answer is a handout value within this share (values are rounded when
#: typed: alpha = 0.5236 rad).
AS_TYPED = 1e-3
#: A numeric answer's relative tolerance when the rubric does not say (3 significant figures).
NUMERIC_TOLERANCE = 0.01

# --- the student's own coordinates ---------------------------------------------------------------

#: Newton's iterations that map the student's coordinates to the statement's stop when the
#: residual is below this relative size.
COORDINATE_MAP = 1e-8
