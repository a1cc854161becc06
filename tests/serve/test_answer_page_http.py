"""`lagrade serve` at the HTTP level, with raw connections: every path that is not a student's
page is 404 with the security headers (never a redirect, whose Location would come from the
client's Host header), a request's head and body have read deadlines (slowloris), and a client
that disconnects mid-body costs one line in the log."""

from __future__ import annotations

import asyncio
import http.client
import socket
import threading
import time
from urllib.parse import urlsplit

import pytest
import uvicorn
from starlette.applications import Starlette
from starlette.requests import ClientDisconnect, Request
from starlette.responses import PlainTextResponse
from starlette.routing import Route

from lagrade.grading.answer_page.deadlines import ReadDeadlines

SECURITY_HEADERS = {
    "cache-control": "no-store",
    "x-content-type-options": "nosniff",
    "referrer-policy": "no-referrer",
    "x-frame-options": "DENY",
}


def _address(served) -> tuple[str, int]:
    parts = urlsplit(served.base)
    return parts.hostname, parts.port


def _request(served, method: str, path: str, body: bytes | None = None, host: str = ""):
    connection = http.client.HTTPConnection(*_address(served), timeout=30)
    headers = {"Host": host} if host else {}
    if body is not None:
        headers["Content-Type"] = "application/json"
    connection.request(method, path, body=body, headers=headers)
    response = connection.getresponse()
    text = response.read().decode()
    connection.close()
    return response.status, {k.lower(): v for k, v in response.getheaders()}, text


def test_every_path_that_is_not_a_page_is_404_with_the_headers(served):
    token = urlsplit(served.url("s001")).path.rsplit("/", 1)[1]
    body = b'{"problem": 1, "key": "dof", "text": "1"}'
    cases = [
        ("GET", f"/s/{token}/", None),  # a trailing slash: a 307 to the Host header's site
        ("GET", f"/s/{token}//", None),
        ("GET", f"/s/{token}%2F", None),
        ("GET", f"//s/{token}", None),
        ("GET", f"/s/{token}/preview", None),
        ("POST", f"/s/{token}/preview/", body),
        ("POST", f"/s/{token}/save/", b'{"answers": {}}'),
        ("PUT", f"/s/{token}", body),
        ("OPTIONS", f"/s/{token}", None),
        ("DELETE", f"/s/{token}/save", None),
        ("GET", "/", None),
        ("GET", "/s", None),
        ("GET", "/static/page.js/", None),
        ("GET", "/static/", None),
        ("GET", "/static/../s", None),
    ]
    for method, path, data in cases:
        status, headers, text = _request(served, method, path, data, host="evil.example")
        assert status == 404, (method, path, status)
        assert "location" not in headers, (method, path)
        assert text == "Not found.", (method, path)
        for name, value in SECURITY_HEADERS.items():
            assert headers.get(name) == value, (method, path, name)
        assert "default-src 'none'" in headers.get("content-security-policy", "")
    # the page itself, with its query string or a HEAD, is still the page
    for method, path in (("GET", f"/s/{token}?x=1"), ("HEAD", f"/s/{token}")):
        status, headers, _ = _request(served, method, path)
        assert status == 200 and headers["x-frame-options"] == "DENY", (method, path)


def _new_log_lines(served, before: int, wait: float = 20.0) -> list[str]:
    """The server's log lines after the first `before`, once some have come (and a second
    more, for the rest of a traceback)."""
    deadline = time.monotonic() + wait
    while time.monotonic() < deadline:
        lines = served.output.read_text().splitlines()[before:]
        if lines:
            time.sleep(1.0)
            return served.output.read_text().splitlines()[before:]
        time.sleep(0.1)
    return []


def test_a_client_that_disconnects_mid_body_is_one_line_in_the_log(served):
    path = urlsplit(served.url("s002")).path + "/save"
    sheet = served.sheets / "s002.toml"
    saved = sheet.read_bytes() if sheet.exists() else None
    for _ in range(2):  # each time one line
        before = len(served.output.read_text().splitlines())
        with socket.create_connection(_address(served), timeout=10) as sock:
            head = (
                f"POST {path} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                "Content-Length: 10000\r\n\r\n"
            )
            sock.sendall(head.encode() + b'{"answers": {"1": {"dof": "')
            time.sleep(0.3)
        lines = _new_log_lines(served, before)
        assert len(lines) == 1, lines
        assert "disconnected before sending its whole save request" in lines[0]
        assert path.rsplit("/", 2)[1] not in lines[0]  # the student's token is not logged
    assert (sheet.read_bytes() if sheet.exists() else None) == saved  # nothing written


def test_lagrade_serve_closes_a_connection_whose_head_never_ends(served):
    """One header line every 2 s: uvicorn alone would wait for ever."""
    start = time.monotonic()
    with socket.create_connection(_address(served), timeout=30) as sock:
        sock.sendall(b"GET /s/x HTTP/1.1\r\nHost: x\r\n")
        closed = None
        for k in range(12):
            time.sleep(2)
            try:
                sock.sendall(f"X-Slow-{k}: 1\r\n".encode())
                if sock.recv(1, socket.MSG_DONTWAIT) == b"":
                    closed = time.monotonic() - start
                    break
            except BlockingIOError:
                continue
            except OSError:
                closed = time.monotonic() - start
                break
    assert closed is not None, "the connection stayed open for 24 s"
    assert ReadDeadlines.head_seconds <= closed < ReadDeadlines.head_seconds + 4


# --- the deadlines themselves, on a small application and short deadlines -----------------------


class _Quick(ReadDeadlines):
    head_seconds = 0.6
    body_seconds = 0.6


@pytest.fixture
def quick_server():
    """uvicorn with `_Quick` deadlines on a thread, serving an application that reads the body
    (and records the clients that went away)."""
    gone: list[str] = []

    async def echo(request: Request):
        try:
            body = await request.body()
        except ClientDisconnect:
            gone.append("disconnected")
            return PlainTextResponse("", status_code=400)
        return PlainTextResponse(f"{len(body)} bytes")

    app = Starlette(routes=[Route("/", echo, methods=["GET", "POST"])])
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    config = uvicorn.Config(app, http=_Quick, log_level="warning", lifespan="off")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=lambda: asyncio.run(server.serve(sockets=[sock])))
    thread.start()
    while not server.started:
        time.sleep(0.05)
    yield sock.getsockname(), gone
    server.should_exit = True
    thread.join(10)


def _closed_after(sock: socket.socket, limit: float) -> float | None:
    """Seconds until the server closes `sock` (reading whatever it answers), or None."""
    start = time.monotonic()
    sock.settimeout(limit)
    try:
        while sock.recv(4096):
            pass
    except TimeoutError:
        return None
    return time.monotonic() - start


def test_a_slow_head_is_closed_at_its_deadline(quick_server):
    address, _ = quick_server
    with socket.create_connection(address) as sock:
        sock.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n")  # and nothing more
        closed = _closed_after(sock, 5)
    assert closed is not None and closed < 0.6 + 1.0


def test_a_slow_body_is_closed_at_its_deadline_and_the_application_sees_it(quick_server):
    address, gone = quick_server
    with socket.create_connection(address) as sock:
        sock.sendall(b"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n\r\n0123456789")
        closed = _closed_after(sock, 5)
    assert closed is not None and closed < 0.6 + 1.0
    time.sleep(0.2)
    assert gone == ["disconnected"]


def test_a_prompt_client_is_answered_and_kept_alive(quick_server):
    address, _ = quick_server
    connection = http.client.HTTPConnection(*address, timeout=5)
    for _ in range(3):  # three requests on one connection, with pauses under the deadline
        connection.request("POST", "/", body=b"x" * 1000)
        response = connection.getresponse()
        assert response.status == 200 and response.read() == b"1000 bytes"
        time.sleep(0.4)
    connection.close()


def test_the_next_head_on_a_kept_alive_connection_has_a_deadline_too(quick_server):
    address, _ = quick_server
    with socket.create_connection(address) as sock:
        sock.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n\r\n")
        time.sleep(0.2)
        assert b"0 bytes" in sock.recv(4096)
        sock.sendall(b"GET / HTTP/1.1\r\n")  # the next request's head never ends
        closed = _closed_after(sock, 5)
    assert closed is not None and closed < 0.6 + 1.0
