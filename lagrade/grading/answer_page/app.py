"""The answer page as a web application (Starlette): one private page per student.

    GET  /s/<token>            the student's handout, one field per part, preview and save
    POST /s/<token>/preview    {"problem": 1, "key": "eom", "text": "…"} → how it is read
    POST /s/<token>/save       {"answers": {"1": {"eom": "…"}}, "attempt": "…"} → the sheet
                               written and logged (and, when the assignment allows, graded
                               with feedback), or refused after the due date (`saving`)
    GET  /static/page.js, /static/page.css   the page's own script and style (no CDN)

Any other path (a trailing slash included: never a redirect), and any token that is not a
roster student's, is 404 with no data. Judging runs in killable worker processes, one item of
each student at a time (`judging`); a save holds that student's lock, so two saves never
interleave, and is appended to the log of saves (`lagrade.grading.savelog`)."""

from __future__ import annotations

import asyncio
import contextlib
import functools
import logging
from collections.abc import Mapping
from importlib import resources
from typing import Any

from starlette.applications import Starlette
from starlette.requests import ClientDisconnect, Request
from starlette.responses import HTMLResponse, JSONResponse, PlainTextResponse, Response
from starlette.routing import Route

import lagrade.untrusted as untrusted
from lagrade.assign import environment
from lagrade.errors import UnreadableInput
from lagrade.grading.answer_page import saving
from lagrade.grading.answer_page.room import ClassRoom
from lagrade.grading.answer_page.sheets import MAX_ANSWER_CHARS, saved_answers

#: The largest request body accepted (every answer of a sheet together).
MAX_BODY_BYTES = 512 * 1024
_log = logging.getLogger("uvicorn.error")
_HEADERS = {
    "Cache-Control": "no-store",
    "X-Content-Type-Options": "nosniff",
    "Referrer-Policy": "no-referrer",
    "X-Frame-Options": "DENY",
    "Content-Security-Policy": (
        "default-src 'none'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
        "img-src 'self' data:; connect-src 'self'; form-action 'none'; frame-ancestors 'none'"
    ),
}


def _not_found() -> Response:
    return PlainTextResponse("Not found.", status_code=404, headers=_HEADERS)


def _json(data: Any, status: int = 200) -> Response:
    return JSONResponse(data, status_code=status, headers=_HEADERS)


def _student(room: ClassRoom, request: Request) -> str | None:
    return room.tokens.get(request.path_params.get("token", ""))


async def _body(request: Request) -> Any:
    """The JSON body, bounded and read by the project's untrusted-input reader. A client that
    goes away before its body is complete raises ClientDisconnect (see `_gone`)."""
    data = bytearray()
    async for chunk in request.stream():
        data += chunk
        if len(data) > MAX_BODY_BYTES:
            raise UnreadableInput(f"the request is larger than {MAX_BODY_BYTES // 1024} KiB")
    return untrusted.load_json(untrusted.decode(bytes(data), "the request"), "the request")


def _gone(request: Request) -> Response:
    """A client that disconnected before its request was complete: one line in the log (the
    route named without its token, which is the student's key), nothing written."""
    action = request.url.path.rsplit("/", 1)[-1]
    host = request.client.host if request.client else "?"
    _log.warning("lagrade: %s disconnected before sending its whole %s request", host, action)
    return Response(status_code=400, headers=_HEADERS)


def make_app(room: ClassRoom) -> Starlette:
    """The web application serving `room`."""
    env = environment()
    page = env.get_template("answer_page.html.j2")

    async def student_page(request: Request) -> Response:
        student_id = _student(room, request)
        if student_id is None:
            return _not_found()
        loop = asyncio.get_running_loop()
        views = await room.views(student_id)  # the drawing thread, never the saves' executor
        answers, warnings = saved_answers(room.submissions, room.manifest, student_id)
        used = await loop.run_in_executor(None, room.log.attempts_used, student_id)
        html = page.render(
            base=f"/s/{request.path_params['token']}",
            assignment=room.assignment,
            student=room.students[student_id],
            problems=views,
            answers=answers,
            warnings=warnings,
            settings=room.settings,
            due=saving.due_view(room),
            attempts_used=used,
            max_chars=MAX_ANSWER_CHARS,
        )
        return HTMLResponse(html, headers=_HEADERS)

    async def preview(request: Request) -> Response:
        student_id = _student(room, request)
        if student_id is None:
            return _not_found()
        try:
            body = await _body(request)
            entry, part, text = _preview_request(room, student_id, body)
        except ClientDisconnect:
            return _gone(request)
        except (UnreadableInput, ValueError) as error:
            return _json({"status": "error", "message": str(error)}, 400)
        field = (entry.get("index"), part["key"])
        return _json(await room.judging().preview(student_id, field, entry, part, text))

    async def save(request: Request) -> Response:
        student_id = _student(room, request)
        if student_id is None:
            return _not_found()
        try:
            body = await _body(request)
            answers = _answers(room, body)
            token = saving.attempt_token(body)
        except ClientDisconnect:
            return _gone(request)
        except (UnreadableInput, ValueError) as error:
            return _json({"status": "error", "message": str(error)}, 400)
        status, reply = await saving.save(room, student_id, answers, token)
        return _json(reply, status)

    async def static(request: Request) -> Response:
        name = request.path_params["name"]
        if name not in _STATIC:
            return _not_found()
        media = _STATIC[name]
        return Response(_static_text(name), media_type=media, headers=_HEADERS)

    @contextlib.asynccontextmanager
    async def lifespan(app):
        room.judging().start()  # already started by `lagrade serve`, before it listened
        drawing = asyncio.create_task(room.draw_all())  # pages ready before they are asked
        try:
            yield
        finally:
            drawing.cancel()
            with contextlib.suppress(asyncio.CancelledError, RuntimeError):
                await drawing
            room.close()

    routes = [
        Route("/s/{token}", student_page),
        Route("/s/{token}/preview", preview, methods=["POST"]),
        Route("/s/{token}/save", save, methods=["POST"]),
        Route("/static/{name}", static),
    ]
    app = Starlette(routes=routes, lifespan=lifespan)
    # Starlette answers a path with a trailing slash by a redirect whose Location it builds from
    # the request's Host header, without our headers: every path that is not a page is 404.
    app.router.redirect_slashes = False
    app.add_exception_handler(404, lambda request, exc: _not_found())
    app.add_exception_handler(405, lambda request, exc: _not_found())
    app.add_exception_handler(Exception, _server_error)
    return app


def _server_error(request: Request, exc: Exception) -> Response:
    """A bug of ours: 500 with the same headers as every other answer (the traceback is in
    the server's log)."""
    return PlainTextResponse("Internal error.", status_code=500, headers=_HEADERS)


_STATIC = {"page.js": "text/javascript", "page.css": "text/css"}


@functools.cache
def _static_text(name: str) -> str:
    return resources.files("lagrade.grading.answer_page").joinpath(name).read_text("utf-8")


def _problem_index(room: ClassRoom, index: Any) -> int:
    """A problem number from a request (1, or "1" as a JSON object key), checked."""
    if isinstance(index, str) and index.isdigit() and len(index) < 6:
        index = int(index)
    if isinstance(index, int) and not isinstance(index, bool):
        if any(int(p["index"]) == index for p in room.manifest["problems"]):
            return index
    raise ValueError("no such problem")


def _part_of(room: ClassRoom, index: Any, key: Any) -> tuple[int, Mapping[str, Any]]:
    number = _problem_index(room, index)
    problem = next(p for p in room.manifest["problems"] if int(p["index"]) == number)
    for part in problem["parts"]:
        if part["key"] == key:
            return number, part
    raise ValueError(f"problem {number} has no part {untrusted.clip(str(key), 40)!r}")


def _text(value: Any) -> str:
    if not isinstance(value, str):
        raise ValueError("an answer must be text")
    if len(value) > MAX_ANSWER_CHARS:
        raise ValueError(f"an answer may be at most {MAX_ANSWER_CHARS:,} characters")
    return value


def _preview_request(room: ClassRoom, student_id: str, body: Any) -> tuple[dict, dict, str]:
    if not isinstance(body, dict):
        raise ValueError("the request must be a JSON object")
    index, part = _part_of(room, body.get("problem"), body.get("key"))
    text = _text(body.get("text", ""))
    entry = room.students[student_id]["problems"][index - 1]
    return dict(entry), dict(part), text


def _answers(room: ClassRoom, body: Any) -> dict[int, dict[str, str]]:
    """The answers of a save request, every problem and key checked against the manifest."""
    if not isinstance(body, dict) or not isinstance(body.get("answers"), dict):
        raise ValueError('the request must be {"answers": {problem: {part: text}}}')
    out: dict[int, dict[str, str]] = {}
    for index, table in body["answers"].items():
        number = _problem_index(room, index)
        if not isinstance(table, dict):
            raise ValueError(f"problem {number}: the answers must be an object")
        for key, value in table.items():
            _part_of(room, number, key)
            out.setdefault(number, {})[key] = _text(value)
    return out
