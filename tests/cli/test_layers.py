"""The layered house, held on the real import graph: every `import` and `from … import` of every
module of lagrade, at any depth (inside functions too), may name only its own layer's package or
a layer below. Same-layer packages (judge and assign) never import each other. The bank sits above
the notation layer: its scenes are files whose expressions the notation layer reads (the same
safe grammar as students' answers), so bank may import notation and notation never the bank.
"""

import ast
import pathlib

import lagrade

ROOT = pathlib.Path(lagrade.__file__).parent

#: Each layer package and the lagrade packages it may import (errors.py and untrusted.py, the
#: error tree and the one reader of unvetted bytes, sit under them all).
ALLOWED = {
    "mechanics": {"mechanics"},
    "bank": {"bank", "notation", "mechanics"},
    "notation": {"notation", "mechanics"},
    "judge": {"judge", "notation", "bank", "mechanics"},
    "assign": {"assign", "notation", "bank", "mechanics"},
    "grading": {"grading", "judge", "assign", "notation", "bank", "mechanics"},
    "cli": {"cli", "grading", "judge", "assign", "notation", "bank", "mechanics"},
}


def _imports(path: pathlib.Path) -> list[tuple[int, str]]:
    """(line, absolute module) for every import in the file, relative ones resolved."""
    package = path.relative_to(ROOT.parent).with_suffix("").parts
    package = package[:-1]  # the package the module lives in
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = list(package[: len(package) - node.level + 1])
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            found.append((node.lineno, module))
            found += [(node.lineno, f"{module}.{a.name}") for a in node.names]
    return found


def _layer(module: str) -> str | None:
    parts = module.split(".")
    if parts[0] != "lagrade" or len(parts) < 2:
        return None
    return parts[1] if parts[1] in ALLOWED else None


def test_every_module_belongs_to_a_layer():
    loose = [
        p.relative_to(ROOT).as_posix()
        for p in ROOT.glob("*.py")
        if p.name not in ("__init__.py", "__main__.py", *FOUNDATION)
    ]
    assert loose == [], "a module outside every layer: put it in the layer that owns it"


#: Root modules under every layer: they may import only each other.
FOUNDATION = ("errors.py", "untrusted.py", "exports.py", "recent.py")


def test_the_foundation_imports_no_layer():
    offenders = [
        f"{name}:{line} imports {module}"
        for name in FOUNDATION
        for line, module in _imports(ROOT / name)
        if _layer(module) is not None
    ]
    assert offenders == []


def test_layers_only_look_down():
    offenders = []
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT)
        if len(rel.parts) < 2:
            continue  # the front door and the error tree
        own = rel.parts[0]
        for line, module in _imports(path):
            target = _layer(module)
            if target is not None and target not in ALLOWED[own]:
                offenders.append(f"{rel}:{line} imports {module} ({own} → {target})")
    assert offenders == []


def test_the_front_door_loads_nothing_heavy():
    """`import lagrade` and the CLI's entry module must not pull in sympy (start-up time)."""
    import subprocess
    import sys

    code = "import sys, lagrade, lagrade.cli.main; print('sympy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_a_layer_is_entered_only_through_its_front_door():
    """Another layer is imported through its package (`from lagrade.judge import judge`), and
    only names its `__init__` exports (`__all__`): never a submodule (`lagrade.judge.driver`),
    so that what a layer offers the others is the list in its `__init__`, pinned by
    test_public_api.py (issue 34: 175 imports reached past a layer's door). The rule is the
    count's own (`benchmarks/layer_counts.py`)."""
    from benchmarks.layer_counts import past_exports

    assert past_exports() == []


def test_a_recent_memo_keeps_the_most_recently_used_within_its_size():
    """`lagrade.recent.Recent`: what the derivation and reading caches keep. A key asked for
    again is kept over one asked for once; past `size` the least recently used goes."""
    from lagrade.recent import Recent

    memo, made = Recent(2), []

    def make(key):
        made.append(key)
        return key.upper()

    assert memo.made("a", lambda: make("a")) == "A"
    assert memo.made("b", lambda: make("b")) == "B"
    assert memo.made("a", lambda: make("a")) == "A"  # kept: not made again, now most recent
    assert memo.made("c", lambda: make("c")) == "C"  # "b", least recently used, goes
    assert list(memo) == ["a", "c"] and made == ["a", "b", "c"]
    assert memo.recalled("b") is None and memo.recalled("a") == "A"
    assert list(memo) == ["c", "a"]


def test_a_recent_memo_keeps_a_value_and_says_what_it_dropped():
    """`Recent.keep`: a value kept anew or again is the most recently used; what went past
    `size` is returned (the question cache forgets that question's preparations with it)."""
    from lagrade.recent import Recent

    memo = Recent(2)
    assert memo.keep("a", 1) is None and memo.keep("b", 2) is None
    assert memo.keep("a", 3) is None  # kept again: replaced, now the most recent
    assert list(memo.items()) == [("b", 2), ("a", 3)]
    assert memo.keep("c", 4) == ("b", 2)
    assert list(memo) == ["a", "c"]
