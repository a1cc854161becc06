"""Judging beyond one machine: `grade` and `check --batch` with `--dask SCHEDULER` send chunks of
sheets or request lines to the workers of a Dask cluster (`local` starts one on this machine;
`tcp://host:port` joins a running one), where each chunk is judged by lagrade's own killable
pool, so that the time and memory limits hold exactly as on one machine; the parent puts the
results back in order and writes every output as it does without Dask. A Dask worker that dies
costs nothing: its chunk is run again elsewhere.

Dask's distributed scheduler is the optional extra `lagrade[dask]`, imported only by a run that
asks for a cluster. The modules: `connect` (reaching a cluster), `chunks` (cutting the work and
running it), `on_worker` (what runs inside a Dask worker), `grading` and `checking` (the two
commands' sides in the parent)."""

from __future__ import annotations

from typing import Any

from lagrade.grading.cluster.connect import require

__all__ = ["check_on_cluster", "grade_on_cluster", "require"]


def __getattr__(name: str) -> Any:
    if name == "grade_on_cluster":
        from lagrade.grading.cluster.grading import grade_on_cluster

        return grade_on_cluster
    if name == "check_on_cluster":
        from lagrade.grading.cluster.checking import check_on_cluster

        return check_on_cluster
    raise AttributeError(f"module 'lagrade.grading.cluster' has no attribute {name!r}")
