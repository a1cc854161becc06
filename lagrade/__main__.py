"""`python -m lagrade` is the `lagrade` command."""

from lagrade.cli.main import entry

entry()
