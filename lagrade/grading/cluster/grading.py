"""`lagrade grade --dask`: the sheets judged on a Dask cluster, everything else as on one machine.

What crosses to the cluster: the manifest's problems and carried scene texts, the rubric and the
limits, once per worker (`on_worker.hold`); per chunk, each student's manifest entry and their
sheet's bytes, read here (a cluster does not share this machine's files), or why they could not
be read; back, each sheet's Outcome. The parent writes every output atomically as it does
without Dask (`lagrade.grading.batch`), so the two give the same files.
"""

from __future__ import annotations

import json
import uuid
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from lagrade.grading.cluster.chunks import chunk_size, cut, describe, run_chunks
from lagrade.grading.cluster.connect import connect, threads
from lagrade.grading.cluster.on_worker import error_outcome, grade_chunk, hold
from lagrade.grading.rubric import Rubric
from lagrade.grading.student import asked_questions, part_spec, structure_key
from lagrade.grading.submission import read_regular_file
from lagrade.judge import Limits, Outcome

#: Chunks in flight per thread of the cluster: one running, one waiting, so that a thread never
#: idles between chunks; the rest wait here, unread.
AHEAD_PER_THREAD = 2


def grade_on_cluster(
    scheduler: str,
    manifest: Mapping[str, Any],
    rubric: Rubric,
    tasks: list[tuple[str, dict[str, Any]]],
    jobs: int,
    limits: Limits,
    version: str,
) -> Iterator[Outcome]:
    """The Outcome of each (student id, task) of `tasks`, as each chunk comes back (the order
    is the caller's to restore), judged on the cluster `scheduler` names (`jobs`: the workers
    of a local one)."""
    if not tasks:
        return
    texts = _scene_texts(manifest)
    problems_only = {k: v for k, v in manifest.items() if k != "students"}
    run = uuid.uuid4().hex  # this run's state on each worker; the next run starts afresh
    shared = {
        "run": run,
        "manifest": problems_only,
        "rubric": rubric,
        "limits": limits,
        "texts": texts,
        "asked": asked_questions(manifest),
    }
    with connect(scheduler, jobs) as client:
        held = client.submit(hold, shared, pure=False)
        width = threads(client)
        ordered = cut(tasks, _questions_of, chunk_size(len(tasks), width))
        chunks = ((chunk, (held, _with_bytes(chunk), version)) for chunk in ordered)
        for chunk, result in run_chunks(client, grade_chunk, chunks, AHEAD_PER_THREAD * width):
            if isinstance(result, BaseException):
                reason = f"the Dask cluster could not judge this sheet: {describe(result)}"
                yield from (error_outcome(key, reason) for key, _task in chunk)
            else:
                yield from result


def _questions_of(item: tuple[str, dict[str, Any]]) -> str:
    """The questions a student's sheet asks (their symbolic form, not the numbers): sheets
    asking the same go to the same chunks, whose worker derives them once."""
    student = item[1]["student"]
    keys = [structure_key(part_spec(entry, {"part": ""})) for entry in student["problems"]]
    return json.dumps(keys)


def _scene_texts(manifest: Mapping[str, Any]) -> dict[str, str]:
    """The text of each scene the students' entries carry, by scene id (sent once)."""
    texts: dict[str, str] = {}
    for student in manifest["students"]:
        for entry in student["problems"]:
            if entry.get("scene_text") is not None:
                texts[entry["scene"]] = entry["scene_text"]
    return texts


def _with_bytes(chunk: list[tuple[str, dict[str, Any]]]) -> list[tuple[str, dict[str, Any]]]:
    """The chunk's tasks as they cross: each sheet's bytes (or why they cannot be read) in place
    of the reading, the scene texts left out (they travelled with the manifest)."""
    out = []
    for key, task in chunk:
        student = dict(task["student"])
        student["problems"] = [
            {k: v for k, v in entry.items() if k != "scene_text"} for entry in student["problems"]
        ]
        content = read_regular_file(Path(task["path"]))
        out.append((key, {**task, "student": student, "content": content}))
    return out
