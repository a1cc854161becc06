"""uvicorn's HTTP/1.1 protocol with read deadlines, against clients that send a request slowly to
hold connections open (slowloris): the head of a request must arrive within `head_seconds` of
the connection (or of the previous response), and its body within `body_seconds` of its head;
otherwise the connection is closed. uvicorn alone times out only a kept-alive connection on
which nothing arrives; one byte every few seconds holds it for ever."""

from __future__ import annotations

import asyncio

from uvicorn.protocols.http.h11_impl import H11Protocol


class ReadDeadlines(H11Protocol):
    """`lagrade serve`'s HTTP protocol (uvicorn's `http=` class)."""

    #: Seconds for a request's head (request line and headers) to arrive.
    head_seconds: float = 10.0
    #: Seconds for its body (at most 512 KiB) to arrive once the head has.
    body_seconds: float = 30.0

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        self._read_deadline: asyncio.TimerHandle | None = None
        self._read_cycle = None  # the request whose head has arrived, if its body has not
        self._arm(self.head_seconds)

    def data_received(self, data: bytes) -> None:
        super().data_received(data)
        self._follow()

    def on_response_complete(self) -> None:
        super().on_response_complete()
        if not self.transport.is_closing():
            self._read_cycle = None
            self._arm(self.head_seconds)  # the next request's head, or the rest of this body
            self._follow()  # a pipelined request parsed just now

    def connection_lost(self, exc: Exception | None) -> None:
        self._disarm()
        super().connection_lost(exc)

    def _follow(self) -> None:
        """Move the deadline along with what has arrived: a new head starts the body's clock,
        a complete body stops the clock (the response is the application's business)."""
        cycle = self.cycle
        if cycle is None or cycle.response_complete:
            return
        if cycle is not self._read_cycle:  # the head of a new request has arrived
            self._read_cycle = cycle
            self._arm(self.body_seconds)
        if not cycle.more_body:
            self._disarm()

    def _arm(self, seconds: float) -> None:
        self._disarm()
        self._read_deadline = self.loop.call_later(seconds, self._expire)

    def _disarm(self) -> None:
        if self._read_deadline is not None:
            self._read_deadline.cancel()
            self._read_deadline = None

    def _expire(self) -> None:
        """Too slow: close the connection (an application waiting for the body sees the client
        go away)."""
        self._read_deadline = None
        if not self.transport.is_closing():
            self.transport.close()
