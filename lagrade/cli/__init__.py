"""Layer 4: the `lagrade` command, one module per command; each parses its arguments, makes one
library call and prints the result."""

from lagrade.cli.main import main

__all__ = ["main"]
