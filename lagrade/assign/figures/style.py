"""The look every figure shares: its three inks, the line styles of traced paths, and the
matplotlib settings that keep SVG and PDF output byte-identical across runs."""

from __future__ import annotations

INK, GREY, ACCENT = "#222222", "#8a8a8a", "#1f5fa8"
#: Grey for text (an axis's name): GREY is 3.45:1 on white, enough for a line (WCAG 1.4.11
#: asks 3:1) but not for text (1.4.3 asks 4.5:1); this is 5.3:1.
GREY_TEXT = "#6b6b6b"

#: How a traced path is drawn: a constraint surface, a coordinate's sweep, a motion in time.
TRACE_STYLE = {
    "solid": dict(color=INK, linewidth=1.4, zorder=1),
    "path": dict(color=GREY, linewidth=0.8, linestyle=(0, (2, 2)), zorder=1),
    "time": dict(color=GREY, linewidth=0.8, linestyle=(0, (6, 3)), zorder=1),
}

#: A fixed hash salt for SVG ids and text kept as text: the same figure gives the same bytes.
RC = {
    "svg.hashsalt": "lagrade",
    "svg.fonttype": "none",
    "pdf.compression": 6,
    "font.size": 11,
    "mathtext.fontset": "dejavuserif",
    "path.simplify": False,
}
