"""`lagrade serve MANIFEST --submissions DIR`: each student's answer page at a private link
(`lagrade.grading.answer_page`), saving the answer sheets `lagrade grade` reads."""

from __future__ import annotations

import argparse
import signal
import socket
import threading
from pathlib import Path

from lagrade.cli.arguments import count
from lagrade.errors import OutputError, RequestError


def run(args: argparse.Namespace) -> int:
    import uvicorn

    from lagrade.grading import (
        SECRET_NAME,
        ReadDeadlines,
        atomic,
        build_classroom,
        links_csv,
        load_manifest,
        load_or_create_secret,
        make_app,
    )

    if not 0 <= args.port <= 65535:
        raise RequestError(f"--port {args.port} is not a port number (0 to 65535)")
    manifest = load_manifest(args.manifest)
    secret_file = args.secret or args.manifest.parent / SECRET_NAME
    secret = load_or_create_secret(secret_file)
    args.submissions.mkdir(parents=True, exist_ok=True)
    room = build_classroom(manifest, args.manifest, args.submissions, secret, jobs=args.jobs)
    room.judging().start()  # fork the workers' host while this process has no socket or thread
    listener = _listen(args.host, args.port)
    host, port = listener.getsockname()[:2]
    base_url = (args.base_url or f"http://{_url_host(host)}:{port}").rstrip("/")
    if args.links:
        atomic.write_text(args.links, links_csv(manifest["students"], secret, base_url))
    config = uvicorn.Config(
        make_app(room),
        http=ReadDeadlines,  # a request's head and body have deadlines (slowloris)
        log_level="warning",
        access_log=False,
        lifespan="on",
        timeout_graceful_shutdown=5,
    )
    server = uvicorn.Server(config)

    def stop_before_start(_signum: int, _frame: object) -> None:
        # a stop that arrives between the announcement and uvicorn's own handlers (which
        # replace this one while it serves, and hand a caught signal back to it at the end)
        server.should_exit = True

    stops = (signal.SIGINT, signal.SIGTERM)
    in_main_thread = threading.current_thread() is threading.main_thread()  # signals' only one
    previous = {stop: signal.signal(stop, stop_before_start) for stop in stops if in_main_thread}
    try:
        _announce(args, room.assignment.title, len(manifest["students"]), listener, base_url)
        print(f"  due date: {_due_line(room.due)}")
        print(f"  secret: {secret_file} (same secret, same links)")
        print("Stop with Ctrl-C (or SIGTERM).", flush=True)
        server.run(sockets=[listener])  # Ctrl-C or SIGTERM: a graceful stop, exit 0
    finally:
        room.close()
        listener.close()
        for stop, handler in previous.items():
            signal.signal(stop, handler)
    print("Stopped: every save was written before the server stopped.", flush=True)
    return 0


def _announce(
    args: argparse.Namespace, title: str, students: int, listener: socket.socket, base_url: str
) -> None:
    host, port = listener.getsockname()[:2]
    print(f"Answer pages for {students} students of {title!r}")
    print(f"  listening on http://{_url_host(host)}:{port}/  (links use {base_url}/s/<token>)")
    from lagrade.grading import LOG_NAME

    print(
        f"  sheets are saved to {args.submissions}/<id>.toml, every save logged in "
        f"{args.submissions}/{LOG_NAME}"
    )
    if args.links:
        print(f"  each student's link: {args.links} (id,name,url)")
    else:
        print("  no --links file: give --links LINKS.csv to write every student's link")


def _due_line(due) -> str:
    """What the page does about the due date, for the instructor who starts the server."""
    from lagrade.grading import shown

    if due.unread:
        return f"not kept ({due.unread}); saves are accepted at any time"
    if due.due is None:
        return "none; saves are accepted at any time"
    if not due.late:
        return f"{shown(due.due)}; after it, saves are refused"
    until = f" until {shown(due.late_until)}, then refused" if due.late_until else ""
    return f"{shown(due.due)}; after it, saves are recorded as late{until}"


def _listen(host: str, port: int) -> socket.socket:
    """The listening socket, bound here so that a port in use is one clear line, not a log."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    # IPPROTO_TCP, not 0: asyncio sets TCP_NODELAY only on sockets that say they are TCP, and
    # without it every keep-alive reply waits ~40 ms for a delayed ACK (Nagle)
    sock = socket.socket(family, socket.SOCK_STREAM, socket.IPPROTO_TCP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind((host, port))
    except OSError as error:
        sock.close()
        raise OutputError(
            f"cannot listen on {host}:{port}: {error.strerror or error}"
            + (" (another server uses it; choose another --port)" if port else "")
        ) from None
    sock.listen(256)
    return sock


def _url_host(host: str) -> str:
    return f"[{host}]" if ":" in host else host


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    serve = commands.add_parser(
        "serve",
        help="serve each student an answer page at a private link",
        description="Serve each roster student a private page with their own handout, one "
        "field per part with a live 'read as' preview, and a save button that writes the "
        "answer sheet `lagrade grade` reads, every save appended to a log beside the sheets "
        "(`lagrade grade --as-of TIME` grades the last save before a time). A "
        "wrong or missing token gets 404. The due date is the assignment's `due`; late work, "
        "feedback on save and its attempts are set in its [answer_page] table.",
        epilog="example: lagrade serve ps3/manifest.json --submissions ps3-submissions "
        "--links ps3-links.csv --port 8000",
    )
    serve.add_argument("manifest", type=Path, metavar="MANIFEST", help="the manifest.json")
    serve.add_argument(
        "--submissions", type=Path, required=True, help="folder the answer sheets are saved in"
    )
    serve.add_argument("--host", default="127.0.0.1", help="address to listen on (127.0.0.1)")
    serve.add_argument("--port", type=int, default=8000, help="port (8000; 0 picks a free one)")
    serve.add_argument("--links", type=Path, help="write every student's link here (CSV)")
    serve.add_argument(
        "--base-url",
        help="the address students reach (behind a proxy), e.g. https://ps.example.edu",
    )
    serve.add_argument(
        "--secret",
        type=Path,
        help="file holding the links' secret (default: .lagrade-serve-secret beside the "
        "manifest; made when absent)",
    )
    serve.add_argument(
        "--jobs", type=count, default=2, help="worker processes for previews and grading (2)"
    )
    serve.set_defaults(run=run)
