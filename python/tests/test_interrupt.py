"""Ctrl-C during a long call (docs/python.md, "Ctrl-C"): a SIGINT sent while stresses,
make_operator or solve_contact runs raises KeyboardInterrupt within about a second, and the
objects the call was given stay usable. Each call is sized to run for far longer than the test
waits (tens of seconds at least), so that only the interrupt can end it in time; a call that
ignored the signal fails the test by its time, and the signal is then raised at its end."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import coatfft
from conftest import quiet_operator, radius

DELAY = 0.25  # [s] from the start of the call to the SIGINT (the calls run for tens of seconds)
# [s] from the SIGINT to the exception: about 0.1 s measured; generous for a loaded machine,
# far below what the calls would take.
RESPONSE = 5.0


@pytest.fixture(autouse=True)
def default_sigint_handler():
    """Python's own SIGINT handler, also where the test runner was started with SIGINT ignored
    (a background job of a shell)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def interrupt(call, delay=DELAY):
    """Runs call() and sends this process SIGINT after `delay`; returns the exception the call
    raised and the seconds from the signal to it."""
    sent = []

    def send():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(delay, send)
    timer.start()
    try:
        call()
    except BaseException as e:  # noqa: B902 (KeyboardInterrupt is what is tested)
        raised = e
    else:
        raised = None
    end = time.monotonic()
    timer.join()
    assert sent, "the call ended before the signal: it is too short for this test"
    return raised, end - sent[0]


def check_interrupted(call):
    raised, seconds = interrupt(call)
    assert isinstance(raised, KeyboardInterrupt), f"raised {raised!r}"
    assert seconds < RESPONSE, f"KeyboardInterrupt {seconds:.1f} s after SIGINT"
    return seconds


@pytest.fixture(scope="module")
def coated(steel, tin):
    return coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-4)])


def test_stresses(coated):
    # 24 planes at 192^2 cells with tractions: minutes.
    grid = coatfft.Grid(192, 192, 4e-3, 4e-3)
    p = coatfft.hertz_pressure(grid, 1e9, 1e-3, "cell_average")
    q = 0.3 * p
    depths = list(np.linspace(2e-5, 6e-4, 24))
    check_interrupted(lambda: coatfft.stresses(coated, grid, depths, p, q, q, alpha=16))
    # The module computes on: a small call afterwards gives what it gives on its own.
    small = coatfft.Grid(16, 16, 4e-3, 4e-3)
    s = coatfft.stresses(coated, small, [1e-4], coatfft.hertz_pressure(small, 1e9, 1e-3,
                                                                       "cell_average"))
    assert np.isfinite(s).all()


def test_make_operator(steel, tin):
    # frf-dcfft at alpha = 16 on 512^2 cells: an FRF lattice of 4096^2 wavenumbers, each a
    # solve through six layers.
    layers = [coatfft.Coating(tin if n % 2 == 0 else steel, 2e-5) for n in range(6)]
    body = coatfft.LayerStack(steel, layers)
    grid = coatfft.Grid(512, 512, 4e-3, 4e-3)
    check_interrupted(lambda: quiet_operator(grid, body, method="frf-dcfft", alpha=16))


@pytest.fixture(scope="module")
def contact_case(steel):
    grid = coatfft.Grid(256, 256, 0.8e-3, 0.8e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    return op, radius(grid) ** 2 / (2 * 0.01)


def endless_solve(op, height):
    # A tolerance no iteration reaches: the solve runs until its iteration limit, minutes away.
    return coatfft.solve_contact(op, height, load=100.0, tolerance=1e-300,
                                 max_iterations=10**7)


def test_solve_contact_leaves_the_operator_usable(contact_case):
    op, height = contact_case
    p = np.ones_like(height)
    before = op.apply(p)
    out = np.zeros_like(height)
    check_interrupted(lambda: endless_solve(op, height))
    np.testing.assert_array_equal(op.apply(p, out=out), before)
    result = coatfft.solve_contact(op, height, load=100.0)
    assert result.converged


def test_a_handler_of_the_users_raises_its_own_exception(contact_case):
    op, height = contact_case

    class Stop(Exception):
        pass

    def handler(signum, frame):
        raise Stop()

    previous = signal.signal(signal.SIGINT, handler)
    try:
        raised, seconds = interrupt(lambda: endless_solve(op, height))
    finally:
        signal.signal(signal.SIGINT, previous)
    assert isinstance(raised, Stop), f"raised {raised!r}"
    assert seconds < RESPONSE


def test_a_handler_that_does_not_raise_lets_the_call_go_on(contact_case):
    op, height = contact_case
    seen = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: seen.append(signum))
    try:
        raised, _ = interrupt(
            lambda: coatfft.solve_contact(op, height, load=100.0, tolerance=1e-300,
                                          max_iterations=300), delay=0.2)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert raised is None
    assert seen == [signal.SIGINT]
