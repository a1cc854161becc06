"""`python -m lagrade` is the `lagrade` command."""

from lagrade.cli import entry

entry()
