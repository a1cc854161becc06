"""A part's prompt as HTML, with the names its answer may use: shared by the PrairieLearn
questions and the answer page, so both ask exactly what the handout asks."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any


def prompt_html(part: Mapping[str, Any]) -> str:
    """A part view's prompt and the names its answer may use, as HTML (escaped here)."""
    prompt = part["prompt"]
    lines = [str(getattr(prompt, "html", None) or escape_html(prompt))]
    for group in part["symbols"]:
        names = ", ".join(f"<code>{escape_html(n)}</code>" for n in group["names"])
        lines.append(
            f'<span class="small">{escape_html(group["what"]).capitalize()}: {names}.</span>'
        )
    return "<br>".join(lines)


def escape_html(text: Any) -> str:
    return str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
