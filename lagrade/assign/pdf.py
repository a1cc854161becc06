"""PDF from the generated LaTeX: pdflatex run on one file, its by-products kept in a scratch
folder; and the warning, with the command that installs it, when pdflatex is missing."""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

TEX_PACKAGES = ("texlive-latex-base",)
PDFLATEX_HINT = (
    "pdflatex is not installed, so no PDF was made (the .tex files are written). Install it "
    "with: apt-get install --no-install-recommends " + " ".join(TEX_PACKAGES)
)


def compile_pdf(pdflatex: str, tex: Path, env: dict[str, str], timeout: float = 120) -> str | None:
    """Compile `tex` next to itself (so `../figures/…` resolves); None, or why it failed."""
    with tempfile.TemporaryDirectory(prefix="lagrade-tex-") as build:
        try:
            run = subprocess.run(
                [
                    pdflatex,
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
            return f"pdflatex took more than {timeout:g} s"
        pdf = Path(build) / (tex.stem + ".pdf")
        if run.returncode != 0 or not pdf.exists():
            log = run.stdout.decode("utf-8", "replace").splitlines()
            first = next((line for line in log if line.startswith("!")), "see the LaTeX log")
            return f"pdflatex failed: {first}"
        shutil.move(str(pdf), tex.with_suffix(".pdf"))
    return None
