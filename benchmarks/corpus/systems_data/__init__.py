"""The systems of the systems corpus, one module per kind of source (see build_systems.py)."""
