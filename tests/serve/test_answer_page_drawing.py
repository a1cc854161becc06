"""A class opening its pages at once never holds up a save: a page's views are drawn in a
thread of their own, and a save's writing runs beside it (`ClassRoom.drawer`). The test holds
every drawing until a save has been answered, through the application itself (ASGI, no
server): before, the pages' drawing took every thread of the executor that saves write with,
so the save could not finish until the drawing was let go. No clock decides it: the save
either completes while the drawing is held or, after a minute, the test says it never did."""

from __future__ import annotations

import asyncio
import json
import threading
from pathlib import Path

from lagrade.grading.answer_page.app import make_app
from lagrade.grading.answer_page.room import build_classroom

from .conftest import generate_class

#: More pages than the default executor has threads on any machine (min(32, cores + 4)).
OPENING = 40


async def call(app, method: str, path: str, body: dict | None = None) -> tuple[int, bytes]:
    """One request through the ASGI application, as a server would pass it."""
    data = json.dumps(body).encode() if body is not None else b""
    scope = {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": method,
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "query_string": b"",
        "headers": [(b"host", b"testserver"), (b"content-type", b"application/json")],
        "client": ("127.0.0.1", 1),
        "server": ("testserver", 80),
    }
    sent = False
    status, chunks = 0, []

    async def receive():
        nonlocal sent
        if not sent:
            sent = True
            return {"type": "http.request", "body": data, "more_body": False}
        await asyncio.Event().wait()  # never disconnects

    async def send(message):
        nonlocal status
        if message["type"] == "http.response.start":
            status = message["status"]
        elif message["type"] == "http.response.body":
            chunks.append(message.get("body", b""))

    await app(scope, receive, send)
    return status, b"".join(chunks)


def test_a_save_is_answered_while_a_whole_class_s_pages_are_being_drawn(tmp_path: Path):
    manifest_path = generate_class(tmp_path)  # a class of three, made a class of OPENING + 1
    manifest = json.loads(manifest_path.read_text())
    one = manifest["students"][0]
    manifest["students"] = [
        {**one, "id": f"s{k:03d}", "name": f"Student {k}"} for k in range(OPENING + 1)
    ]
    sheets = tmp_path / "sheets"
    sheets.mkdir()
    room = build_classroom(manifest, manifest_path, sheets, b"k" * 32)
    token = {sid: t for t, sid in room.tokens.items()}
    held = threading.Event()
    drawing = room.problems_of

    def slow_drawing(student_id):
        held.wait(120)
        return drawing(student_id)

    room.problems_of = slow_drawing
    app = make_app(room)

    async def class_opens() -> tuple[int, bytes]:
        pages = [
            asyncio.create_task(call(app, "GET", f"/s/{token[f's{k:03d}']}"))
            for k in range(1, OPENING + 1)
        ]
        await asyncio.sleep(0.5)  # every page is in its drawing
        answers = {"answers": {"1": {"dof": "1"}}}
        try:
            saved = await asyncio.wait_for(
                call(app, "POST", f"/s/{token['s000']}/save", answers), timeout=60
            )
        except TimeoutError:
            saved = (0, b"the save was not answered while the pages were being drawn")
        held.set()
        assert {status for status, _ in await asyncio.gather(*pages)} == {200}
        return saved

    try:
        status, body = asyncio.run(class_opens())
    finally:
        held.set()
        room.close()
    assert status == 200, body
    assert json.loads(body)["status"] == "saved"
    assert (sheets / "s000.toml").exists()
