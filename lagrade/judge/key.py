"""A variant's answer key as a student would type it: `key_answer` lives in
`lagrade.notation.keys`, below both judge and assign, so that the key `generate` prints and the
key the grader checks before it are one function."""

from lagrade.notation import key_answer

__all__ = ["key_answer"]
