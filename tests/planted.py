"""A checker planted for the tests of the kill rule: an answer holding `HANG` makes it spin in
one C call, where no Python signal handler (so no alarm) runs until it returns. Real answers
that held a worker in C once existed (an exact stage multiplying multi-megabit integers), but the
judge now bounds its own work before it starts, so the kill at limit + grace is tested with
this plant, whatever the judge's bounds become.

`install()` patches the checker the one driver calls for every entry point
(`lagrade.judge.driver.run_checker`) and every part's reader of the reading step
(`lagrade.judge.read.READERS`, what a preview runs); forked workers inherit
both. A server started in a process
of its own installs it with `python -c "import tests.planted as p; p.install(); ..."`."""

from __future__ import annotations

HANG = "zzhang"


def spinning(real):
    def spin_on_hang(problem, part, answer, given=None):
        if HANG in str(answer):
            sum(range(10**13))  # one C call: no Python signal handler runs until it returns
        return real(problem, part, answer, given)

    return spin_on_hang


def spinning_reader(real):
    def spin_on_hang(problem, answer):
        if HANG in str(answer):
            sum(range(10**13))  # one C call, as above
        return real(problem, answer)

    return spin_on_hang


def install() -> None:
    import lagrade.judge.driver as driver
    from lagrade.judge.read import READERS

    driver.run_checker = spinning(driver.run_checker)
    for part, reader in list(READERS.items()):
        READERS[part] = spinning_reader(reader)
