"""The counts issue 34 asked for, from the code as it stands (read, never run):

  imports past a layer's exports   cross-layer imports that name another layer's submodule, or a
                                   name that layer's `__init__` does not export (`__all__`)
  tolerance literals               numeric literals below 1e-3 (and decimals below 0.01) in the
                                   judge outside its named constants (`lagrade/judge/tolerances.py`
                                   and UPPER_CASE names), docstrings, floors against a division by
                                   zero (below 1e-100) and lines marked `# not a tolerance`
  equivalence implementations      places that compute one of the equivalence tests, found by the
                                   shape of their code (a constant per parameter group is
                                   `searchsorted(group, group)`; a scale is a least-squares ratio;
                                   a row space an SVD or `lstsq` over stacked rows)

Run: python benchmarks/layer_counts.py [--list]
"""

from __future__ import annotations

import argparse
import ast
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "lagrade"
LAYERS = ("mechanics", "notation", "bank", "judge", "assign", "grading", "cli")


def _layer_of(path: Path) -> str | None:
    parts = path.relative_to(ROOT).parts
    return parts[0] if len(parts) > 1 and parts[0] in LAYERS else None


def _exports(layer: str) -> set[str]:
    tree = ast.parse((ROOT / layer / "__init__.py").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets
        ):
            return {ast.literal_eval(e) for e in node.value.elts}
    return set()


def past_exports() -> list[str]:
    """Every cross-layer import that reaches past the other layer's front door."""
    exports = {layer: _exports(layer) for layer in LAYERS}
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        own = _layer_of(path)
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                parts = node.module.split(".")
                if parts[0] != "lagrade" or len(parts) < 2 or parts[1] not in LAYERS:
                    continue
                other = parts[1]
                if other == own:
                    continue
                names = [a.name for a in node.names]
                if len(parts) > 2 or any(n not in exports[other] for n in names):
                    found.append(f"{path.relative_to(ROOT.parent)}:{node.lineno}: {node.module}")
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    parts = alias.name.split(".")
                    if len(parts) > 2 and parts[0] == "lagrade" and parts[1] in LAYERS:
                        if parts[1] != own:
                            found.append(
                                f"{path.relative_to(ROOT.parent)}:{node.lineno}: {alias.name}"
                            )
    return found


_SMALL = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?[eE]-\d+|0\.00\d*)(?![\w.])")
_CONSTANT = re.compile(r"^\s*[A-Z][A-Z0-9_]*\s*(?::[^=]+)?=")


def tolerance_literals() -> list[str]:
    """Small numeric literals in the judge outside named constants, strings (docstrings) and
    lines marked `# not a tolerance` (a unit's factor, a range of display)."""
    found = []
    for path in sorted((ROOT / "judge").rglob("*.py")):
        if path.name == "tolerances.py":
            continue
        text = path.read_text(encoding="utf-8")
        strings = _string_lines(text)
        for number, line in enumerate(text.splitlines(), 1):
            code = line.split("#", 1)[0]
            if _CONSTANT.match(code) or number in strings or "# not a tolerance" in line:
                continue
            for match in _SMALL.finditer(code):
                if _in_string(code, match.start()) or float(match.group(1)) < 1e-100:
                    continue  # a string, or a floor against division by zero (1e-300)
                found.append(f"{path.relative_to(ROOT.parent)}:{number}: {match.group(1)}")
    return found


def _string_lines(text: str) -> set[int]:
    """The lines of every multi-line string (docstrings) of a module."""
    lines: set[int] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            if node.end_lineno and node.end_lineno > node.lineno:
                lines.update(range(node.lineno, node.end_lineno + 1))
    return lines


def _in_string(code: str, at: int) -> bool:
    return code[:at].count('"') % 2 == 1 or code[:at].count("'") % 2 == 1


#: The shape of each equivalence test's computation.
_TESTS = {
    "equal up to a constant per parameter group": re.compile(r"searchsorted\(\s*\w*\.?group"),
}


def equivalence_places() -> dict[str, list[str]]:
    found: dict[str, list[str]] = {name: [] for name in _TESTS}
    for path in sorted((ROOT / "judge").rglob("*.py")):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            for name, pattern in _TESTS.items():
                if pattern.search(line):
                    found[name].append(f"{path.relative_to(ROOT.parent)}:{number}")
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--list", action="store_true", help="list every place counted")
    args = parser.parse_args()
    imports, literals, places = past_exports(), tolerance_literals(), equivalence_places()
    print(f"imports past a layer's exports: {len(imports)}")
    if args.list:
        print("".join(f"  {line}\n" for line in imports), end="")
    files = {line.split(":")[0] for line in literals}
    print(f"tolerance literals outside the named constants: {len(literals)} in {len(files)} files")
    if args.list:
        print("".join(f"  {line}\n" for line in literals), end="")
    for name, where in places.items():
        print(f"places that implement '{name}': {len(where)}")
        if args.list:
            print("".join(f"  {line}\n" for line in where), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
