"""Instants as an instructor writes them: the assignment's `due`, `[answer_page] late`, and
`lagrade grade --as-of TIME`. One reading for all three, so that "the due date" means the same
instant to the page that refuses a save and to the grade that picks the last save before it.

    2025-03-14T23:59:00+01:00   that instant
    2025-03-14T23:59:00         that wall-clock time in the assignment's zone
                                (`[answer_page] timezone`, default: this computer's)
    2025-03-14 23:59            the same (a space for the T, seconds optional)
    2025-03-14                  the end of that day (every save on the 14th is on time)

A wall-clock time the zone's clocks never showed (the hour skipped when daylight saving
begins: 2026-03-08T02:30 in America/New_York) or showed twice (the hour repeated when it ends:
2026-11-01T01:30 there) names no single instant: it is refused, saying which it is and how to
write the instant meant (with its offset, which a time written with one always has).
"""

from __future__ import annotations

import datetime as dt
import re
import zoneinfo

from lagrade.errors import RequestError

#: Day, then an optional time (T or a space) with optional seconds and fraction, then an
#: optional offset (Z or ±hh:mm): the ISO 8601 forms TOML and people write.
_INSTANT = re.compile(
    r"^(?P<date>\d{4}-\d{2}-\d{2})"
    r"(?:[T ](?P<time>\d{2}:\d{2}(?::\d{2}(?:\.\d{1,6})?)?)"
    r"(?P<offset>Z|[+-]\d{2}:?\d{2})?)?$"
)
_EPOCH = dt.datetime(1970, 1, 1, tzinfo=dt.UTC)


def zone(name: str | None) -> dt.tzinfo | None:
    """The time zone called `name` (IANA: "Europe/Berlin", "UTC"), or None for this computer's
    local time; RequestError for a name the zone database does not have."""
    if name is None:
        return None
    try:
        return zoneinfo.ZoneInfo(name)
    except (zoneinfo.ZoneInfoNotFoundError, ValueError):
        raise RequestError(
            f"unknown time zone {name!r} (write an IANA name such as 'Europe/Berlin' or 'UTC')"
        ) from None


def read_instant(text: str, where: dt.tzinfo | None = None) -> dt.datetime:
    """The instant `text` names (module docstring), timezone-aware; RequestError naming the
    accepted forms when it names none."""
    text = str(text).strip()
    match = _INSTANT.match(text)
    if match is None:
        raise RequestError(
            f"{text[:60]!r} is not a date and time (write 2025-03-14T23:59:00, optionally with "
            "an offset such as +01:00 or Z, or a date alone for the end of that day)"
        )
    try:
        if match["time"] is None:
            day = dt.date.fromisoformat(match["date"])
            moment = dt.datetime.combine(day, dt.time(23, 59, 59, 999_999))
        else:
            moment = dt.datetime.fromisoformat(
                f"{match['date']}T{match['time']}{match['offset'] or ''}"
            )
    except ValueError as error:
        raise RequestError(f"{text[:60]!r} is not a valid date and time ({error})") from None
    if moment.tzinfo is not None:
        return moment
    _one_instant(moment, where, text[:60])
    if where is None:
        return moment.astimezone()  # a naive time is this computer's local time (DST included)
    return moment.replace(tzinfo=where)


def _one_instant(wall: dt.datetime, where: dt.tzinfo | None, text: str) -> None:
    """RequestError when the wall-clock time `wall` in `where` (None: this computer's zone)
    is in a daylight-saving gap or fold. Python reads such a time either way (`fold` 0 and 1
    give different instants); a time the clocks showed once reads back as itself both ways."""
    readings = [_reading(wall.replace(fold=fold), where) for fold in (0, 1)]
    if readings[0] == readings[1]:
        return
    shows = [r.astimezone(where).replace(tzinfo=None) == wall for r in readings]
    place = getattr(where, "key", None) or "this computer's time zone"
    first, second = (r.astimezone(where) for r in readings)
    if all(shows):  # a fold: the clocks showed this time twice
        raise RequestError(
            f"{text!r} happens twice in {place}, when the clocks go back (at "
            f"{_offset(first)} {first.strftime('%Z')} and again at {_offset(second)} "
            f"{second.strftime('%Z')}): write the offset of the one you mean, e.g. "
            f"{wall.isoformat(timespec='minutes')}{_offset(first)}"
        )
    # a gap: fold 0 reads the time with the offset before the jump, which lands after it
    later, earlier = first, second
    raise RequestError(
        f"{text!r} never happens in {place}: the clocks skip that hour when daylight saving "
        f"begins (from {_offset(earlier)} {earlier.strftime('%Z')} to {_offset(later)} "
        f"{later.strftime('%Z')}); write a time the clocks show, or an offset"
    )


def _reading(wall: dt.datetime, where: dt.tzinfo | None) -> dt.datetime:
    """`wall` (with its `fold`) read in `where` as an instant in UTC."""
    if where is None:
        return dt.datetime.fromtimestamp(wall.timestamp(), dt.UTC)
    return wall.replace(tzinfo=where).astimezone(dt.UTC)


def _offset(moment: dt.datetime) -> str:
    """The UTC offset of an aware time as ISO 8601 writes it: `-05:00`."""
    return moment.isoformat()[-6:]


def shown(moment: dt.datetime) -> str:
    """An instant as the page shows it: `2025-03-14 23:59 CET` (seconds when not :00)."""
    exact = moment.second == 0 and moment.microsecond == 0
    form = "%Y-%m-%d %H:%M" if exact else "%Y-%m-%d %H:%M:%S"
    name = moment.strftime("%Z") or moment.strftime("UTC%z")
    return f"{moment.strftime(form)} {name}"


def utc_text(moment: dt.datetime) -> str:
    """An instant as the log stores it: UTC, ISO 8601, microseconds (`…T22:59:00.000000+00:00`)."""
    return moment.astimezone(dt.UTC).isoformat(timespec="microseconds")


def from_ns(ns: int) -> dt.datetime:
    """The instant `ns` nanoseconds after the Unix epoch, in UTC."""
    return _EPOCH + dt.timedelta(microseconds=ns // 1000)


def to_ns(moment: dt.datetime) -> int:
    """Nanoseconds after the Unix epoch (exact to the microsecond, which is what it holds)."""
    delta = moment - _EPOCH
    return (delta.days * 86_400 + delta.seconds) * 1_000_000_000 + delta.microseconds * 1000
