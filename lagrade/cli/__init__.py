"""Layer 4: the `lagrade` command, one module per command; each parses its arguments, makes one
library call and prints the result."""

from __future__ import annotations

# a name that is also a module of this package is bound here, so that importing the module (which
# sets the package's attribute to it) never shadows it
from lagrade.cli.main import main
from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "entry": "lagrade.cli.main",
}
#: The modules exported as a whole.
_MODULES = {}

__all__ = ["entry", "main"]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
