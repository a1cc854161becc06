"""Layer 4: the `lagrade` command, one module per command; each parses its arguments, makes one
library call and prints the result."""

from __future__ import annotations

from importlib import import_module
from typing import Any

# a name that is also a module of this package is bound here, so that importing the module (which
# sets the package's attribute to it) never shadows it
from lagrade.cli.main import main

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "entry": "lagrade.cli.main",
}
#: The modules exported as a whole.
_MODULES = {}

__all__ = ["entry", "main"]


def __getattr__(name: str) -> Any:
    if name in _MODULES:
        value = import_module(_EXPORTS[name])
    elif name in _EXPORTS:
        value = getattr(import_module(_EXPORTS[name]), name)
    else:
        raise AttributeError(f"module 'lagrade.cli' has no attribute {name!r}")
    globals()[name] = value
    return value
