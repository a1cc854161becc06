"""PDF from the generated LaTeX, for a name in any script. pdflatex typesets what it can (most
Latin names) and is the fast path; a document it cannot typeset (Đặng Thị Ngọc Hà, 王小明,
Αλέξανδρος) is compiled again with LuaLaTeX, whose preamble (in the templates) sets Latin
Modern with Noto Serif and Noto Serif CJK as fallback fonts. Both run with `\\tracinglostchars=3`,
so a character no font has is an error naming it, never a blank left silently in a name. A
document neither engine can typeset is reported with the reason, and left out of the manifest
(`pipeline`), never passed off as written."""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

#: Debian's packages for the PDFs: TeX Live's pdflatex, LuaLaTeX with fontspec, and the fonts
#: LuaLaTeX falls back on (Latin, Greek, Cyrillic, Vietnamese: Noto Serif; CJK: Noto Serif CJK).
TEX_PACKAGES = (
    "texlive-latex-base",
    "texlive-latex-recommended",
    "texlive-luatex",
    "fonts-noto-core",
    "fonts-noto-cjk",
)
ENGINES = ("pdflatex", "lualatex")
PDFLATEX_HINT = (
    "pdflatex is not installed, so no PDF was made (the .tex files are written). Install it "
    "with: apt-get install --no-install-recommends " + " ".join(TEX_PACKAGES)
)


def engines() -> list[str]:
    """The LaTeX engines on PATH, pdflatex first (fast), then lualatex (any script)."""
    return [found for name in ENGINES if (found := shutil.which(name))]


def compile_pdf(
    engines: list[str] | str, tex: Path, env: dict[str, str], timeout: float = 120
) -> str | None:
    """Compile `tex` next to itself (so `../figures/…` resolves) with the first engine that
    typesets it; None, or why none could (each engine's first error)."""
    tried = []
    for engine in [engines] if isinstance(engines, str) else engines:
        problem = _compile(engine, tex, env, timeout)
        if problem is None:
            return None
        tried.append(f"{Path(engine).name}: {problem}")
    return "; ".join(tried) or "no LaTeX engine is installed"


def _compile(engine: str, tex: Path, env: dict[str, str], timeout: float) -> str | None:
    with tempfile.TemporaryDirectory(prefix="lagrade-tex-") as build:
        try:
            run = subprocess.run(
                [
                    engine,
                    "-interaction=nonstopmode",
                    "-halt-on-error",
                    "-no-shell-escape",
                    f"-output-directory={build}",
                    tex.name,
                ],
                cwd=tex.parent,
                env=env,
                capture_output=True,
                timeout=timeout,
                check=False,
            )
        except subprocess.TimeoutExpired:
            return f"took more than {timeout:g} s"
        pdf = Path(build) / (tex.stem + ".pdf")
        if run.returncode != 0 or not pdf.exists():
            log = run.stdout.decode("utf-8", "replace").splitlines()
            first = next((line for line in log if line.startswith("!")), "see the LaTeX log")
            return first.removeprefix("! ")
        shutil.move(str(pdf), tex.with_suffix(".pdf"))
    return None
