"""Resident memory of a process and of the processes it started, from /proc (Linux): what the
memory benchmarks sample while a run goes on."""

from __future__ import annotations

import os


def vm_rss(pid: int) -> int:
    """VmRSS of `pid` in kB (0 once it has gone)."""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def descendants(root: int) -> list[int]:
    """The processes started by `root`, at any depth (a scan of /proc/*/stat)."""
    parents = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat", "rb") as f:
                    stat = f.read()
                parents[int(entry)] = int(stat.rsplit(b")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                pass
    found, frontier = [], {root}
    while frontier:
        frontier = {pid for pid, parent in parents.items() if parent in frontier}
        found += sorted(frontier)
    return found


def tree_rss(root: int) -> tuple[int, dict[int, int]]:
    """(RSS of `root`, {descendant pid: its RSS}) in kB."""
    return vm_rss(root), {pid: vm_rss(pid) for pid in descendants(root)}
