"""`python -m lagrade` is the `lagrade` command."""

import sys

from lagrade.cli.main import main

sys.exit(main())
