#!/usr/bin/python3
"""`vplant test` at scale (docs/benchmarks.md, "Suites"): prints figures, checks nothing.

  1. scenarios/regression one case after the other (a `vplant run` per file in a loop, and
     `vplant test -j 1`) against `vplant test -j 2`: wall time and speed-up;
  2. a sweep of the reference plant with N cases (default 1000: 10 loads x 100 friction values)
     at -j 2: wall time, cases per second, and the peak memory (the largest resident set of
     `vplant test` and of any one case; the suite's total is about that times the jobs).

Usage: tools/bench/suite_bench.py VPLANT [--cases N] [--skip-regression] [--skip-sweep]
The load average before each part is printed: other work on the machine slows it down.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def load_average():
    return "load average %.2f %.2f %.2f" % os.getloadavg()


def timed(argv, cwd):
    start = time.monotonic()
    done = subprocess.run(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return time.monotonic() - start, done


def sweep_scenario(cases):
    """The reference plant without its outputs, with a matrix of `cases` combinations."""
    with open(os.path.join(SOURCE, "scenarios/reference-plant.yaml")) as f:
        lines = f.read().splitlines()
    text, skipping = [], False
    for line in lines:
        if line.startswith("outputs:"):
            skipping = True
            continue
        if skipping and (line.startswith(" ") or line.startswith("\t")):
            continue
        skipping = False
        text.append(line)
    loads = 10 if cases >= 10 else 1
    frictions = cases // loads
    text.append("matrix:")
    text.append("  plant.cyl.load_force: [%s]" % ", ".join(str(1000 + 500 * i) for i in range(loads)))
    text.append("  plant.cyl.viscous_friction: [%s]" % ", ".join(str(1000 + 10 * i) for i in range(frictions)))
    return "\n".join(text) + "\n", loads * frictions


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vplant")
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--skip-regression", action="store_true")
    ap.add_argument("--skip-sweep", action="store_true")
    a = ap.parse_args()
    vplant = os.path.abspath(a.vplant)
    print("cores: %d" % os.cpu_count())

    if not a.skip_regression:
        regression = os.path.join(SOURCE, "scenarios/regression")
        cases = len(subprocess.run([vplant, "test", regression, "--list"], stdout=subprocess.PIPE, text=True,
                                   check=True).stdout.split("\n")) - 1
        print("\nscenarios/regression: %d cases" % cases)
        files = sorted(os.path.join(regression, f) for f in os.listdir(regression) if f.endswith(".yaml"))
        with tempfile.TemporaryDirectory() as tmp:
            print("  before the loop: %s" % load_average())
            start = time.monotonic()
            for f in files:
                subprocess.run([vplant, "run", f, "--quiet"], cwd=tmp, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            loop = time.monotonic() - start
            print("  before -j 1: %s" % load_average())
            serial, r1 = timed([vplant, "test", regression, "-j", "1"], tmp)
            print("  before -j 2: %s" % load_average())
            parallel, r2 = timed([vplant, "test", regression, "-j", "2"], tmp)
            print("  after:       %s" % load_average())
        if r1.returncode or r2.returncode:
            print("  (a run did not pass: exit %d / %d)" % (r1.returncode, r2.returncode))
        print("  a vplant run per file, one after the other: %.2f s wall" % loop)
        print("  one after the other (-j 1): %.2f s wall" % serial)
        print("  vplant test -j 2:           %.2f s wall" % parallel)
        print("  speed-up:                   %.2fx" % (serial / parallel))

    if not a.skip_sweep:
        text, n = sweep_scenario(a.cases)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "reference-plant-sweep.yaml")
            with open(path, "w") as f:
                f.write(text)
            print("\nreference plant sweep: %d cases (6 s simulated each), -j 2" % n)
            print("  before: %s" % load_average())
            wall, r = timed([vplant, "test", path, "-j", "2", "--junit", os.path.join(tmp, "junit.xml")], tmp)
            print("  after:  %s" % load_average())
            summary = [line for line in r.stdout.splitlines() if " cases: " in line]
            print("  exit %d; %s" % (r.returncode, summary[-1] if summary else "no summary"))
            print("  wall: %.1f s, %.1f cases/s, %.0f ms per case per core" % (wall, n / wall, 2000 * wall / n))
            print("  junit: %.1f MB" % (os.path.getsize(os.path.join(tmp, "junit.xml")) / 1e6))
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        print("  peak memory: %.1f MB, the largest resident set of vplant test and any one case" % (peak / 1024))
    return 0


if __name__ == "__main__":
    sys.exit(main())
