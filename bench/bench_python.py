#!/usr/bin/python3
"""What a call from Python adds to the library's own work (docs/python.md, "Performance").

- apply: Operator.apply(p) from Python (numpy array in, a new array out, or into an array given
  as `out`) against the same
  operator's apply() timed in C++ (coatfft._coatfft.timing.apply_seconds, into a field allocated
  once) at 64^2 and 1024^2, for Love's DC-FFT on steel and frf-split on TiN 2 um on steel. The
  overhead is the difference of the medians; the two are timed in alternating rounds, so that
  load on the machine reaches both alike.
- frf: coatfft.frf(body, k) on 10^6 wavenumbers (one vectorised call) against a C++ loop of
  H(k) calls over the same array (timing.frf_loop_seconds), for steel and the coated body.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [--out CSV] [--rounds R]
Writes bench/results/python_overhead.csv by default.
"""
import argparse
import datetime
import os
import platform
import statistics
import time

import numpy as np

import coatfft
from coatfft._coatfft import timing


def python_apply_seconds(op, p, repeat, out=None):
    """Median of `repeat` Operator.apply calls from Python (into `out` when given)."""
    seconds = []
    for _ in range(repeat):
        start = time.perf_counter()
        op.apply(p, out=out)
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds)


def python_frf_seconds(body, k, repeat):
    seconds = []
    for _ in range(repeat):
        start = time.perf_counter()
        coatfft.frf(body, k)
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds)


def bodies():
    steel = coatfft.material("steel")
    tin = coatfft.material("titanium_nitride")
    coated = coatfft.LayerStack(steel, [coatfft.Coating(tin, 2e-6)])
    return [("steel", steel, "dcfft"), ("tin_2um_on_steel", coated, "frf-split")]


def apply_rows(rounds):
    rows = []
    for n, repeat in ((64, 200), (1024, 5)):
        grid = coatfft.Grid(n, n, 2e-3, 2e-3)
        p = coatfft.hertz_pressure(grid, 1e9, 0.5e-3)
        for name, body, method in bodies():
            op = coatfft.make_operator(grid, body, method=method)
            op.apply(p)  # warm-up
            out = np.empty(grid.shape)
            py, py_out, cpp = [], [], []
            for _ in range(rounds):
                py.append(python_apply_seconds(op, p, repeat))
                py_out.append(python_apply_seconds(op, p, repeat, out))
                cpp.append(timing.apply_seconds(op, p, repeat))
            cpp_s = statistics.median(cpp)
            for kind, seconds in (("apply", py), ("apply_out", py_out)):
                py_s = statistics.median(seconds)
                rows.append((kind, name, method, n * n, py_s, cpp_s, py_s - cpp_s, py_s / cpp_s))
    return rows


def frf_rows(rounds):
    rows = []
    k = np.logspace(0, 9, 10**6)  # rad/m: 1 m to 1 nm wavelengths
    for name, body, _ in bodies():
        coatfft.frf(body, k)  # warm-up
        py, cpp = [], []
        for _ in range(rounds):
            py.append(python_frf_seconds(body, k, 3))
            cpp.append(timing.frf_loop_seconds(body, k, 3))
        py_s, cpp_s = statistics.median(py), statistics.median(cpp)
        rows.append(("frf", name, "", k.size, py_s, cpp_s, py_s - cpp_s, py_s / cpp_s))
    return rows


def write(path, rows, rounds):
    header = [
        "# bench = bench_python.py",
        f"# date = {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%dT%H:%M:%SZ}",
        f"# cpu = {platform.processor() or platform.machine()}",
        f"# hardware_threads = {os.cpu_count()}",
        f"# python = {platform.python_version()}, numpy {np.__version__}, coatfft {coatfft.__version__}",
        f"# load_average = {os.getloadavg()[0]:.2f}",
        "# apply rows: python_s = median Operator.apply(p) from Python (array in, new array out; "
        "apply_out: into an array given as out=); "
        "cpp_s = median apply() timed in C++ on the same operator and pressure; "
        f"{rounds} alternating rounds, medians of their medians; size = nx * ny",
        "# frf rows: python_s = coatfft.frf(body, k), one call on 1e6 wavenumbers; "
        "cpp_s = C++ loop of H(k) calls over the same array; size = number of wavenumbers",
        "# overhead_s = python_s - cpp_s; ratio = python_s / cpp_s",
        "kind,body,method,size,python_s,cpp_s,overhead_s,ratio",
    ]
    with open(path, "w") as out:
        out.write("\n".join(header) + "\n")
        for kind, body, method, size, py_s, cpp_s, over, ratio in rows:
            out.write(f"{kind},{body},{method},{size},{py_s:.6g},{cpp_s:.6g},{over:.3g},{ratio:.4f}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--out", default=os.path.join(here, "results", "python_overhead.csv"))
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    rows = apply_rows(args.rounds) + frf_rows(args.rounds)
    write(args.out, rows, args.rounds)
    for row in rows:
        print(",".join(str(v) for v in row))


if __name__ == "__main__":
    main()
