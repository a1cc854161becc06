"""Private links: each student's page lives at `/s/<token>`, the token derived from a secret
the instructor keeps, so that links can be made again (same secret, same links) and no token
can be guessed from an id. A wrong token and a missing student look the same: 404."""

from __future__ import annotations

import base64
import csv
import hashlib
import hmac
import io
import os
import secrets
from collections.abc import Iterable, Mapping
from pathlib import Path

import lagrade.grading.atomic as atomic
from lagrade.errors import RequestError
from lagrade.grading.report import csv_cell

#: The secret's file when the instructor names none: beside the manifest, which holds the
#: answer keys and so is already private.
SECRET_NAME = ".lagrade-serve-secret"
_SECRET_BYTES = 32
_TOKEN_CHARS = 32  # base32 of 160 bits of HMAC-SHA256


def load_or_create_secret(path: Path) -> bytes:
    """The secret in `path`, made (32 random bytes, hex, mode 0600) when the file is absent.
    A file that is not a secret this module wrote is refused rather than used weakly."""
    path = Path(path)
    if not path.exists():
        atomic.write_text(path, secrets.token_hex(_SECRET_BYTES) + "\n")
        os.chmod(path, 0o600)
    try:
        text = path.read_text(encoding="ascii").strip()
        secret = bytes.fromhex(text)
    except (OSError, UnicodeDecodeError, ValueError):
        raise RequestError(
            f"{path} is not a secret written by `lagrade serve` (64 hex digits); delete it to "
            "make a new one (every student's link then changes)"
        ) from None
    if len(secret) < 16:
        raise RequestError(f"the secret in {path} is too short (at least 32 hex digits)")
    return secret


def student_token(secret: bytes, student_id: str) -> str:
    """The token in `student_id`'s link: HMAC-SHA256 of the id under the secret, base32."""
    digest = hmac.new(secret, b"lagrade-answer-page\x1f" + student_id.encode(), hashlib.sha256)
    return base64.b32encode(digest.digest()).decode("ascii").lower()[:_TOKEN_CHARS]


def token_table(secret: bytes, student_ids: Iterable[str]) -> dict[str, str]:
    """token → student id, for looking a request up in constant time."""
    return {student_token(secret, sid): sid for sid in student_ids}


def links_csv(students: Iterable[Mapping[str, str]], secret: bytes, base_url: str) -> str:
    """The instructor's list of links, `id,name,url`, one row per roster student."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["id", "name", "url"])
    base = base_url.rstrip("/")
    for student in students:
        url = f"{base}/s/{student_token(secret, student['id'])}"
        writer.writerow([csv_cell(student["id"]), csv_cell(student.get("name", "")), url])
    return out.getvalue()
