"""The answer page under load: 1, 50 and 200 simulated students at once against
`lagrade serve` on 127.0.0.1, each typing (a preview per pause) and saving, in one run; then
20 students (20 rounds each) alone, and the same 20 while two others attack: each sends, again
and again, a preview whose check holds a worker in C code for about 20 s (the limit is 3 s).

Run: python benchmarks/bench_serve.py [--rounds 4] [--jobs 2] [--baseline PATH]
    python benchmarks/bench_serve.py --only opening --baseline PATH   (that row alone)

Each simulated student opens their page, then `--rounds` times: previews three answers of
the kinds students type (right in plain text, LaTeX, a sign mistake, an unreadable one) and
saves the sheet with a marker of its own. Every student stops by itself after its rounds; at
the end every sheet on disk must be that student's own last save (no lost or mixed-up sheet),
and the log of saves must hold every save the server acknowledged, in order, each once.
Reports per level: requests, wall time, median and p99 latency of previews and saves, errors.
Latencies include queueing: with 200 students on 2 cores, a preview waits for the workers.
Under attack, the attackers' replies are reported too: each should be `timeout` within the
preview's limit + grace (5 s).

A class opening at once: a server just started, 30 students open their pages together (30
variants whose views nobody has drawn yet) while one more student, whose page is open, saves:
the openers' median and slowest page, and the bystander's save. With `--baseline PATH` (another
checkout of lagrade) the same row is measured on a server run from that tree, side by side.
"""

from __future__ import annotations

import argparse
import csv
import http.client
import json
import os
import random
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from urllib.parse import urlsplit

from lagrade.assign import generate
from lagrade.grading.savelog import SaveLog, log_path

ASSIGNMENT = """\
title = "Answer page benchmark"
points = 1

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "eom", "momenta"]
names = { theta = ["theta"] }

[[problems]]
scene = "wedge"
parts = [{ quantity = "block_acceleration" }]
"""
#: What an attacker previews: the marker on which the server's planted checker
#: (`tests/planted.py`) spins in one C call that no alarm interrupts. Real answers that did so
#: (an exact stage multiplying multi-megabit integers) are bounded by the judge now; the plant
#: passes every other answer to the real checker unchanged.
SLOW_IN_C = "zzhang"
REPOSITORY = Path(__file__).resolve().parents[1]

ANSWERS = [
    ("lagrangian", "1/2 m l^2 theta_dot^2 + m g l cos(theta)"),
    ("lagrangian", r"\frac{1}{2} m l^{2} \dot{\theta}^{2} + m g l \cos{\theta}"),
    ("lagrangian", "1/2 m l^2 theta_dot^2 - m g l cos(theta)"),  # sign of V
    ("eom", "m l^2 theta_ddot + m g l sin(theta) = 0"),
    ("eom", "m l^2 theta_ddot = m g l sin(theta)"),  # sign
    ("momenta", "p_theta = m l^2 theta_dot"),
    ("eom", "m l^2 (theta_ddot + g sin(theta) = 0"),  # unreadable
    ("dof", "1"),
]
LEVELS = (1, 50, 200)
#: Students previewing and saving, alone and then while two others attack, and their rounds
#: (enough for the attackers' previews to be stopped and sent again several times).
BYSTANDERS = 20
BYSTANDER_ROUNDS = 20


def make_class(root: Path, students: int) -> Path:
    (root / "assignment.toml").write_text(ASSIGNMENT)
    rows = ["id,name"] + [f"b{k:03d},Student {k}" for k in range(students)]
    (root / "roster.csv").write_text("\n".join(rows) + "\n")
    generate(root / "assignment.toml", root / "roster.csv", 7, root / "ps", formats=("md",))
    return root / "ps" / "manifest.json"


def start(
    manifest: Path, sheets: Path, links: Path, jobs: int, tree: Path = REPOSITORY
) -> tuple[subprocess.Popen, str]:
    """The server (lagrade from `tree`), its output in a log file (a pipe nobody reads would
    fill and stall it)."""
    log = manifest.parent / f"server-{sheets.name}.log"
    process = subprocess.Popen(
        [
            sys.executable,
            "-c",
            "import tests.planted as p; p.install(); from lagrade.cli.main import entry; entry()",
            "serve",
            str(manifest),
            "--submissions",
            str(sheets),
            "--links",
            str(links),
            "--port",
            "0",
            "--jobs",
            str(jobs),
        ],
        stdout=log.open("w"),
        stderr=subprocess.STDOUT,
        cwd=tree,  # `python -c` puts the working folder first on sys.path
        env={
            **os.environ,
            "PYTHONPATH": os.pathsep.join(dict.fromkeys([str(tree), str(REPOSITORY)])),
        },
    )
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and process.poll() is None:
        for line in log.read_text().splitlines():
            if "listening on " in line:
                return process, line.split("listening on ")[1].split()[0].rstrip("/")
        time.sleep(0.1)
    raise SystemExit("the server did not start:\n" + log.read_text())


class Student(threading.Thread):
    """One simulated student on one keep-alive connection."""

    def __init__(self, url: str, rounds: int, seed: int) -> None:
        super().__init__(daemon=True)
        parts = urlsplit(url)
        self.host, self.port, self.path = parts.hostname, parts.port, parts.path
        self.rounds, self.random = rounds, random.Random(seed)
        self.previews: list[float] = []
        self.saves: list[float] = []
        self.errors: list[str] = []
        self.last_marker = ""
        self.acknowledged: list[str] = []  # the markers of the saves answered 200

    def request(self, conn, method: str, path: str, body: dict | None = None) -> float:
        data = json.dumps(body).encode() if body is not None else None
        start = time.perf_counter()
        conn.request(method, path, body=data, headers={"Content-Type": "application/json"})
        response = conn.getresponse()
        response.read()
        elapsed = time.perf_counter() - start
        self.status = response.status
        if response.status != 200:
            self.errors.append(f"{method} {path.rsplit('/', 1)[-1]}: {response.status}")
        return elapsed

    def run(self) -> None:
        conn = http.client.HTTPConnection(self.host, self.port, timeout=300)
        try:
            self.request(conn, "GET", self.path)
            for k in range(self.rounds):
                for key, text in self.random.sample(ANSWERS, 3):
                    body = {"problem": 1, "key": key, "text": text}
                    self.previews.append(self.request(conn, "POST", self.path + "/preview", body))
                marker = f"{self.path[-8:]}-{k}"
                answers = {
                    "1": {
                        "dof": "1",
                        "lagrangian": f"m g l cos(theta) + 0*{k}",
                        "momenta": f"p_theta = m l^2 theta_dot  # {marker}",
                    }
                }
                self.saves.append(
                    self.request(conn, "POST", self.path + "/save", {"answers": answers})
                )
                self.last_marker = marker
                if self.status == 200:
                    self.acknowledged.append(marker)
        except (OSError, http.client.HTTPException) as error:
            self.errors.append(f"{type(error).__name__}: {error}")
        finally:
            conn.close()


class Attacker(threading.Thread):
    """A student who previews `SLOW_IN_C` again as soon as each preview is answered."""

    def __init__(self, url: str, stop: threading.Event) -> None:
        super().__init__(daemon=True)
        parts = urlsplit(url)
        self.host, self.port, self.path, self.stop = parts.hostname, parts.port, parts.path, stop
        self.replies: list[tuple[float, str]] = []

    def run(self) -> None:
        conn = http.client.HTTPConnection(self.host, self.port, timeout=300)
        body = json.dumps({"problem": 2, "key": "block_acceleration", "text": SLOW_IN_C})
        try:
            while not self.stop.is_set():
                start = time.perf_counter()
                conn.request("POST", self.path + "/preview", body=body.encode())
                response = conn.getresponse()
                reply = json.loads(response.read())
                self.replies.append((time.perf_counter() - start, reply["status"]))
        except (OSError, http.client.HTTPException, ValueError) as error:
            self.replies.append((0.0, f"{type(error).__name__}: {error}"))
        finally:
            conn.close()


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))] if ordered else 0.0


def run_level(
    links: list[dict], sheets: Path, students: int, rounds: int, attackers: int = 0
) -> dict:
    chosen = links[:students]
    crowd = [Student(row["url"], rounds, seed=k) for k, row in enumerate(chosen)]
    log = SaveLog(log_path(sheets), create=False)
    logged_before = {row["id"]: len(log.saves(row["id"])) for row in chosen}
    stop = threading.Event()
    attacks = [Attacker(row["url"], stop) for row in links[students : students + attackers]]
    for a in attacks:
        a.start()
    if attacks:
        time.sleep(1.0)  # the attacks are in the workers before the students begin
    start = time.perf_counter()
    for s in crowd:
        s.start()
    for s in crowd:
        s.join()
    wall = time.perf_counter() - start
    stop.set()
    for a in attacks:
        a.join()
    replies = [r for a in attacks for r in a.replies]
    previews = [t for s in crowd for t in s.previews]
    saves = [t for s in crowd for t in s.saves]
    errors = [e for s in crowd for e in s.errors]
    mixed = 0
    for row, s in zip(chosen, crowd, strict=True):
        text = (sheets / f"{row['id']}.toml").read_text(encoding="utf-8")
        if f"# {s.last_marker}'" not in text and f"# {s.last_marker}\n" not in text:
            mixed += 1
        if f'student_id = "{row["id"]}"' not in text:
            mixed += 1
    unlogged = 0
    for row, s in zip(chosen, crowd, strict=True):
        rows = log.saves(row["id"])[logged_before[row["id"]] :]
        markers = [r.answers["1"]["momenta"].rsplit("# ", 1)[-1] for r in rows]
        unlogged += abs(len(markers) - len(s.acknowledged)) + sum(
            a != b for a, b in zip(markers, s.acknowledged, strict=False)
        )
    return {
        "students": students,
        "requests": len(previews) + len(saves) + students,
        "wall_s": wall,
        "preview_median_ms": statistics.median(previews) * 1e3,
        "preview_p99_ms": percentile(previews, 0.99) * 1e3,
        "save_median_ms": statistics.median(saves) * 1e3,
        "save_p99_ms": percentile(saves, 0.99) * 1e3,
        "errors": len(errors),
        "lost_or_mixed_sheets": mixed,
        "log_mismatches": unlogged,
        "attacks": len(replies),
        "attack_statuses": sorted({status for _, status in replies}),
        "attack_max_s": max((t for t, _ in replies), default=0.0),
    }


#: A class opening its pages at once (see the module docstring), with an assignment of four
#: problems whose variants differ (names, options, values), as an instructor's would.
OPENING = 30
OPENING_ASSIGNMENT = """\
title = "A class opening its pages"

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "momenta"]

[[problems]]
scene = "spherical_pendulum"
parts = ["lagrangian", "eom"]

[[problems]]
scene = "double_pendulum"
parts = ["lagrangian"]

[[problems]]
scene = "pendulum_on_cart"
parts = ["lagrangian", "conserved"]
"""


def make_opening_class(root: Path) -> Path:
    folder = root / "opening"
    folder.mkdir()
    (folder / "assignment.toml").write_text(OPENING_ASSIGNMENT)
    rows = ["id,name"] + [f"o{k:03d},Student {k}" for k in range(OPENING + 1)]
    (folder / "roster.csv").write_text("\n".join(rows) + "\n")
    generate(folder / "assignment.toml", folder / "roster.csv", 11, folder / "ps", formats=("md",))
    return folder / "ps" / "manifest.json"


def class_opening(manifest: Path, jobs: int, tree: Path, name: str) -> dict:
    """A fresh server from `tree`; OPENING students open their pages together while a
    bystander whose page is open saves again and again (0.5 s after its last save was
    answered) until every page has come."""
    sheets = manifest.parent / f"sheets-{name}"
    links_file = manifest.parent / f"links-{name}.csv"
    process, _ = start(manifest, sheets, links_file, jobs, tree)
    try:
        links = list(csv.DictReader(links_file.open()))
        bystander = Student(links[0]["url"], 0, seed=0)
        conn = http.client.HTTPConnection(bystander.host, bystander.port, timeout=300)
        bystander.request(conn, "GET", bystander.path)
        pages: list[float] = []
        go = threading.Barrier(OPENING + 1)

        def open_page(url: str) -> None:
            student = Student(url, 0, seed=0)
            c = http.client.HTTPConnection(student.host, student.port, timeout=300)
            go.wait()
            pages.append(student.request(c, "GET", student.path))
            c.close()

        openers = [
            threading.Thread(target=open_page, args=(row["url"],), daemon=True)
            for row in links[1 : OPENING + 1]
        ]
        for t in openers:
            t.start()
        start_at = time.perf_counter()
        go.wait()
        saves: list[float] = []
        statuses: set[int] = set()
        while any(t.is_alive() for t in openers) or not saves:
            time.sleep(0.5)  # a student pressing save now and then
            answers = {"1": {"dof": "1", "momenta": f"p_theta = m l^2 theta_dot  # {len(saves)}"}}
            saves.append(
                bystander.request(conn, "POST", bystander.path + "/save", {"answers": answers})
            )
            statuses.add(bystander.status)
        all_open = time.perf_counter() - start_at
        for t in openers:
            t.join()
        conn.close()
        return {
            "tree": name,
            "saves": len(saves),
            "save_max_ms": max(saves) * 1e3,
            "save_median_ms": statistics.median(saves) * 1e3,
            "ok": statuses == {200} and len(pages) == OPENING,
            "page_median_ms": statistics.median(pages) * 1e3,
            "page_max_ms": max(pages) * 1e3,
            "all_open_s": all_open,
        }
    finally:
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=60)


def report_opening(manifest: Path, jobs: int, baseline: Path | None) -> None:
    trees = [("this tree", REPOSITORY)] + ([("baseline", baseline)] if baseline else [])
    print(f"\na class of {OPENING} opening its pages at once, one bystander saving:")
    print(
        f"{'tree':>10} {'saves':>6} {'save med ms':>12} {'save max ms':>12} {'page med ms':>12} "
        f"{'page max ms':>12} {'all open s':>10}"
    )
    for name, tree in trees:
        r = class_opening(manifest, jobs, tree, name.replace(" ", "-"))
        print(
            f"{name:>10} {r['saves']:>6} {r['save_median_ms']:>12.0f} {r['save_max_ms']:>12.0f} "
            f"{r['page_median_ms']:>12.0f} {r['page_max_ms']:>12.0f} {r['all_open_s']:>10.1f}"
            + ("" if r["ok"] else "  (errors)"),
            flush=True,
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=4, help="preview-and-save rounds each")
    parser.add_argument("--jobs", type=int, default=2, help="the server's worker processes")
    parser.add_argument(
        "--baseline", type=Path, default=None, help="another lagrade checkout, for the opening row"
    )
    parser.add_argument(
        "--only", choices=("opening",), default=None, help="run only the class-opening row"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        print(f"generating a class of {max(LEVELS)} (not timed)…", flush=True)
        manifest = make_class(root, max(LEVELS))
        report_opening(make_opening_class(root), args.jobs, args.baseline)
        if args.only:
            return
        process, base = start(manifest, root / "sheets", root / "links.csv", args.jobs)
        try:
            links = list(csv.DictReader((root / "links.csv").open()))
            Student(links[0]["url"], 1, seed=0).run()  # warm the workers (not reported)
            print(
                f"{'students':>8} {'requests':>8} {'wall s':>7} {'preview med':>12} "
                f"{'p99 ms':>8} {'save med':>9} {'p99 ms':>8} {'errors':>6} {'lost/mixed':>10} "
                f"{'unlogged':>8}"
            )
            runs = [(students, args.rounds, 0) for students in LEVELS]
            runs += [(BYSTANDERS, BYSTANDER_ROUNDS, 0), (BYSTANDERS, BYSTANDER_ROUNDS, 2)]
            for students, rounds, attackers in runs:
                r = run_level(links, root / "sheets", students, rounds, attackers)
                label = f"{students}+{attackers}att" if attackers else str(students)
                print(
                    f"{label:>8} {r['requests']:>8} {r['wall_s']:>7.1f} "
                    f"{r['preview_median_ms']:>12.1f} {r['preview_p99_ms']:>8.1f} "
                    f"{r['save_median_ms']:>9.1f} {r['save_p99_ms']:>8.1f} {r['errors']:>6} "
                    f"{r['lost_or_mixed_sheets']:>10} {r['log_mismatches']:>8}",
                    flush=True,
                )
                if attackers:
                    print(
                        f"{'':>8} ({attackers} attackers: {r['attacks']} slow previews answered "
                        f"{', '.join(r['attack_statuses'])}, the slowest in "
                        f"{r['attack_max_s']:.1f} s)",
                        flush=True,
                    )
        finally:
            process.send_signal(signal.SIGTERM)
            process.wait(timeout=30)
            problems = [
                ln
                for ln in (manifest.parent / "server-sheets.log").read_text().splitlines()
                if "Error" in ln or "Traceback" in ln
            ]
            print(
                f"server log: {len(problems)} error lines"
                + "".join(f"\n  {ln}" for ln in problems[:20])
            )


if __name__ == "__main__":
    main()
