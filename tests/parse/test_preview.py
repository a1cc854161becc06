"""The 'interpreted as' preview behind `lagrade parse`."""

from __future__ import annotations

from lagrade.cli.parse import preview_command


def test_preview_of_a_good_answer() -> None:
    status, text = preview_command("1/2 m R^2 thetadot^2", ["theta", "phi"], ["m", "R"], None)
    assert status == 0
    assert text.splitlines() == [
        "Interpreted as: 1/2*m*R^2*theta_dot^2",
        "LaTeX:          \\frac{1}{2} \\cdot m \\cdot R^{2} \\cdot \\dot{\\theta}^{2}",
        "Symbols found:  R, m, theta_dot",
        "Warning: the coordinate phi does not appear (nor its velocity).",
    ]


def test_preview_of_an_error_shows_the_caret() -> None:
    status, text = preview_command("m g sin 2 R", ["theta"], ["m", "g", "R"], None)
    assert status == 1
    assert text == (
        "Ambiguous 'sin' without brackets: write sin(2*R) or sin(2)*R.\n"
        "  m g sin 2 R\n      ^^^^^^^"
    )


def test_preview_with_primes_and_forced_latex() -> None:
    assert preview_command("x'", ["x"], [], None, allow_primes=True)[0] == 0
    status, text = preview_command("x'", ["x"], [], None)  # read, with a note (issue 38)
    assert status == 0 and "Warning: x' is read as x_dot (a prime as d/dt)." in text
    assert "Warning" not in preview_command("x'", ["x"], [], None, allow_primes=True)[1]
    status, text = preview_command(r"\dot{x}_M", ["x_M"], [], True)
    assert status == 0 and "\\dot{x}_{M}" in text
