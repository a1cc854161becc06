"""A package's front door, loaded on first use: each layer's `__init__` lists what it offers the
others (`_EXPORTS`: name → the module that defines it) and gets its `__getattr__` here, so that
importing a layer costs nothing it does not use (`lagrade --help` loads no sympy)."""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from importlib import import_module
from typing import Any


def lazy_exports(
    package: str, exports: Mapping[str, str], modules: Collection[str] = ()
) -> Callable[[str], Any]:
    """The module-level `__getattr__` of `package`: a name of `exports` is imported from its
    module on first use and bound in the package (a name of `modules` is the module itself)."""

    def __getattr__(name: str) -> Any:
        if name in modules:
            value = import_module(exports[name])
        elif name in exports:
            value = getattr(import_module(exports[name]), name)
        else:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        setattr(import_module(package), name, value)
        return value

    return __getattr__
