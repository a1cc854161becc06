"""Figures drawn from a scene's own geometry, so that every scene of the bank (and any new one)
has a picture without drawing code of its own.

The bodies' positions are evaluated at a representative configuration (parameters at the middle
of their value pools or domains, coordinates at a generic pose), and each body's path is traced
as each coordinate sweeps a range: that draws the constraint surfaces (the hoop, the wedge's
face, the incline, a pendulum's arc). A body whose path under an angle is a circle gets a rod
from the circle's centre and an angle mark from where the angle is zero; a length coordinate
gets a dimension arrow from where it is zero. 3-D scenes are drawn in an oblique projection.
What geometry cannot tell (the wedge is a triangle, the hoop has no rod, the oscillators hang
on springs between walls) comes from the scene's `figure` (its scene file's `[figure]` table,
`lagrade.mechanics.figure.FigureHint`); the figure test holds every scene to draw each
body and each spring, rope, pulley, wall and surface its statement names. Labels are kept apart
and everything inside the frame by measuring the rendered artists (`layout`).

Output is SVG and PDF, byte-identical across runs (fixed hash salt, no dates).

Modules, each importing only those before it: `style` (inks, line
styles, matplotlib settings), `geometry` (numeric positions and the questions asked of them),
`primitives` (labels, arrows, marks), `bodies` (bodies and 3-D axes), `fixtures` (springs, dashpots,
ropes, pulleys, walls, surfaces, bars), `plan` (what to draw, in order, each element with its kind),
`layout` (labels apart, everything in frame), `render` (`compose`, and `draw`: SVG and PDF).
"""

from lagrade.assign.figures.geometry import representative_values
from lagrade.assign.figures.render import Composed, Element, Figure, FigureError, compose, draw

__all__ = [
    "Composed",
    "Element",
    "Figure",
    "FigureError",
    "compose",
    "draw",
    "representative_values",
]
